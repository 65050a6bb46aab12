#include "render/state_diagram.h"

#include <map>
#include <set>

#include "engine/core/error.h"

namespace pcsg::render {

namespace {

// GN links: a muted blue, so that they recede behind the LN links they reverse.
constexpr Rgb kGnColour{0.33f, 0.45f, 0.72f};
// A row of more states than this is split: wider diagrams stop being readable on a screen.
constexpr std::size_t kMaxRowStates = 8;

// The rows of the states (by index in graph.states): one per cardinality, the highest (the
// seeds') on top. A cardinality with too many states for one row gets one row per BFS depth
// from the seed (State::depth), and a row still too long is cut into pieces.
std::vector<int> rows_of(const StateGraph& graph) {
  std::map<int, std::map<int, std::vector<int>>, std::greater<int>> by_card;  // card, depth
  for (std::size_t i = 0; i < graph.states.size(); ++i) {
    const State& s = graph.states[i];
    by_card[s.cf.cardinality()][s.depth].push_back(static_cast<int>(i));
  }
  std::vector<int> row(graph.states.size(), 0);
  int next = 0;
  for (const auto& [card, by_depth] : by_card) {
    std::size_t count = 0;
    for (const auto& [depth, members] : by_depth) count += members.size();
    if (count <= kMaxRowStates) {
      for (const auto& [depth, members] : by_depth)
        for (int i : members) row[i] = next;
      ++next;
      continue;
    }
    for (const auto& [depth, members] : by_depth) {
      for (std::size_t k = 0; k < members.size(); ++k) {
        if (k > 0 && k % kMaxRowStates == 0) ++next;
        row[members[k]] = next;
      }
      ++next;
    }
  }
  return row;
}

struct PairLinks {
  bool ln_forward = false, ln_backward = false;  // LN first -> second, second -> first
  bool gn_forward = false, gn_backward = false;
  std::string motion_forward, motion_backward;
};

}  // namespace

Diagram draw_state_diagram(const StateGraph& graph, const SceneGeometry& scene,
                           const std::vector<Image>& pictures, const StateDiagramOptions& o,
                           const TextPainter& text) {
  if (pictures.size() != graph.states.size()) {
    throw Error("draw_state_diagram: " + std::to_string(pictures.size()) + " pictures for " +
                std::to_string(graph.states.size()) + " states");
  }
  std::map<int, int> index_of;  // state id -> node
  const std::vector<int> row = rows_of(graph);
  std::vector<DiagramNode> nodes;
  for (std::size_t i = 0; i < graph.states.size(); ++i) {
    const State& s = graph.states[i];
    index_of[s.id] = static_cast<int>(i);
    DiagramNode n;
    n.picture = pictures[i];
    n.caption = state_caption(s, scene);
    n.row = row[i];
    n.emphasised = s.seed;
    nodes.push_back(std::move(n));
  }
  auto row_of = [&](int id) { return row[index_of.at(id)]; };

  // the links of each neighbouring pair, keyed by (upper, lower): the upper row first, in one
  // row the smaller id; an LN link to a lower cardinality always points down
  std::map<std::pair<int, int>, PairLinks> pairs;
  for (const Link& l : graph.links) {
    if (!index_of.count(l.from) || !index_of.count(l.to)) {
      throw Error("draw_state_diagram: link " + std::to_string(l.from) + " -> " +
                  std::to_string(l.to) + " names a state the graph does not have");
    }
    const bool from_upper =
        row_of(l.from) < row_of(l.to) || (row_of(l.from) == row_of(l.to) && l.from < l.to);
    const auto key = from_upper ? std::make_pair(l.from, l.to) : std::make_pair(l.to, l.from);
    PairLinks& p = pairs[key];
    if (l.kind == LinkKind::LN) {
      (from_upper ? p.ln_forward : p.ln_backward) = true;
      (from_upper ? p.motion_forward : p.motion_backward) = l.motion;
    } else {
      (from_upper ? p.gn_forward : p.gn_backward) = true;
    }
  }
  const bool compact = pairs.size() > o.max_detailed_pairs;
  std::vector<DiagramEdge> edges;
  for (const auto& [key, p] : pairs) {
    const int upper = index_of.at(key.first), lower = index_of.at(key.second);
    if (p.ln_forward || p.ln_backward) {
      DiagramEdge e;
      e.from = upper;
      e.to = lower;
      e.head = p.ln_forward;
      e.tail = p.ln_backward;
      if (o.motion_labels && !compact) {
        // one name when both ways use the same motion; else each with its direction
        const std::string up = std::to_string(graph.states[upper].id),
                          down = std::to_string(graph.states[lower].id);
        if (p.motion_backward.empty() || p.motion_backward == p.motion_forward) {
          e.label = p.motion_forward.empty() ? p.motion_backward : p.motion_forward;
        } else if (p.motion_forward.empty()) {
          e.label = p.motion_backward;
        } else {
          e.label = up + "\xE2\x86\x92" + down + " " + p.motion_forward + "\n" + down +
                    "\xE2\x86\x92" + up + " " + p.motion_backward;
        }
      }
      if (compact && p.gn_backward && !e.tail) e.tail = e.tail_open = true;
      if (compact && p.gn_forward && !e.head) e.head = e.head_open = true;
      edges.push_back(e);
      if (compact) continue;
    }
    if (p.gn_forward || p.gn_backward) {
      DiagramEdge e;
      e.from = upper;
      e.to = lower;
      e.style = LinkStyle::Dashed;
      e.colour = kGnColour;
      e.head = p.gn_forward;
      e.tail = p.gn_backward;
      edges.push_back(e);
    }
  }

  DiagramOptions d;
  d.title = o.title.empty() ? graph.scene : o.title;
  int seeds = 0;
  for (const State& s : graph.states) seeds += s.seed;
  d.subtitle = std::to_string(graph.states.size()) + " states, " +
               std::to_string(graph.links.size()) + " links (" + std::to_string(seeds) +
               (seeds == 1 ? " seed" : " seeds") + "); rows by cardinality, long rows by BFS depth";
  d.legend = {{LinkStyle::Solid, palette::kEdge, "LN link: arrow toward the LN state", false}};
  if (compact) {
    d.legend.push_back({LinkStyle::Solid, palette::kEdge,
                        "GN link: open arrow, the reverse of an LN link to a lower cardinality "
                        "(compact: " + std::to_string(pairs.size()) + " neighbouring pairs)",
                        true});
  } else {
    d.legend.push_back({LinkStyle::Dashed, kGnColour,
                        "GN link: the reverse of an LN link to a lower cardinality", false});
  }
  return draw_diagram(nodes, edges, d, text);
}

}  // namespace pcsg::render
