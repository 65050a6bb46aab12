#include "render/graph_layout.h"

#include <graphviz/gvc.h>

#include <cstdio>
#include <map>
#include <memory>
#include <mutex>

#include "engine/core/error.h"

namespace pcsg::render {

namespace {

// Graphviz works in points (1/72 inch) and takes node sizes in inches. We lay out with one
// point per pixel, so a node of w pixels is w/72 inches wide.
constexpr double kPointsPerInch = 72;

std::mutex& graphviz_mutex() {
  static std::mutex m;
  return m;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

std::string label_table(double width, double height) {
  return "<<TABLE FIXEDSIZE=\"TRUE\" BORDER=\"0\" WIDTH=\"" +
         std::to_string(static_cast<int>(width + 0.5)) + "\" HEIGHT=\"" +
         std::to_string(static_cast<int>(height + 0.5)) + "\"><TR><TD></TD></TR></TABLE>>";
}

bool has_label(const LayoutEdge& e) { return e.label_width > 0 && e.label_height > 0; }

bool flat(const std::vector<LayoutNode>& nodes, const LayoutEdge& e) {
  return nodes[e.from].row >= 0 && nodes[e.from].row == nodes[e.to].row;
}

// The input graph in DOT: fixed-size boxes, rows, edges with an id to find them again. A label
// is an empty HTML table of the label's size (dot then reserves exactly that room, whatever
// font it would have measured text with); on a flat edge it is a node "l<k>" instead, split
// into edges "e<k>a" and "e<k>b" around it.
std::string to_dot(const std::vector<LayoutNode>& nodes, const std::vector<LayoutEdge>& edges,
                   const LayoutOptions& o) {
  std::string s = "digraph \"" + o.name + "\" {\n";
  s += "  graph [rankdir=TB, nodesep=" + number(o.node_gap / kPointsPerInch) +
       ", ranksep=\"" + number(o.rank_gap / kPointsPerInch) + " equally\", splines=true];\n";
  s += "  node [shape=box, fixedsize=true, label=\"\"];\n";
  s += "  edge [dir=none];\n";
  std::map<int, std::vector<std::string>> rows;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const LayoutNode& n = nodes[i];
    s += "  n" + std::to_string(i) + " [width=" + number(n.width / kPointsPerInch) +
         ", height=" + number(n.height / kPointsPerInch) + "];\n";
    if (n.row >= 0) rows[n.row].push_back("n" + std::to_string(i));
  }
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const LayoutEdge& e = edges[k];
    const std::string id = std::to_string(k), from = "n" + std::to_string(e.from),
                      to = "n" + std::to_string(e.to);
    if (has_label(e) && flat(nodes, e)) {
      s += "  l" + id + " [width=" + number(e.label_width / kPointsPerInch) +
           ", height=" + number(e.label_height / kPointsPerInch) + "];\n";
      rows[nodes[e.from].row].push_back("l" + id);
      s += "  " + from + " -> l" + id + " [id=\"e" + id + "a\"];\n";
      s += "  l" + id + " -> " + to + " [id=\"e" + id + "b\"];\n";
      continue;
    }
    s += "  " + from + " -> " + to + " [id=\"e" + id + "\"";
    if (has_label(e)) s += ", label=" + label_table(e.label_width, e.label_height);
    s += "];\n";
  }
  const std::string* previous = nullptr;
  for (const auto& [row, members] : rows) {
    s += "  { rank=same;";
    for (const std::string& m : members) s += " " + m + ";";
    s += " }\n";
    // an invisible edge keeps consecutive rows in order without pulling on the nodes
    if (previous != nullptr) s += "  " + *previous + " -> " + members.front() + " [style=invis, weight=0];\n";
    previous = &members.front();
  }
  return s + "}\n";
}

struct ContextDeleter {
  void operator()(GVC_t* c) const { gvFreeContext(c); }
};

}  // namespace

GraphLayout layout_graph(const std::vector<LayoutNode>& nodes,
                         const std::vector<LayoutEdge>& edges, const LayoutOptions& options) {
  for (const LayoutEdge& e : edges) {
    if (e.from < 0 || e.to < 0 || e.from >= static_cast<int>(nodes.size()) ||
        e.to >= static_cast<int>(nodes.size())) {
      throw Error("layout_graph: edge " + std::to_string(e.from) + " -> " + std::to_string(e.to) +
                  " names a node outside 0.." + std::to_string(nodes.size()) + "-1");
    }
  }
  GraphLayout out;
  if (nodes.empty()) return out;
  const std::string dot = to_dot(nodes, edges, options);

  const std::scoped_lock lock(graphviz_mutex());
  std::unique_ptr<GVC_t, ContextDeleter> gvc(gvContext());
  if (!gvc) throw Error("Graphviz: cannot create a context");
  Agraph_t* g = agmemread(dot.c_str());
  if (g == nullptr) throw Error("Graphviz: cannot parse the generated graph:\n" + dot);
  if (gvLayout(gvc.get(), g, "dot") != 0) {
    agclose(g);
    throw Error("Graphviz: the dot layout failed (is libgvplugin_dot_layout installed?)");
  }
  const boxf bb = GD_bb(g);
  out.width = bb.UR.x - bb.LL.x;
  out.height = bb.UR.y - bb.LL.y;
  // dot's y axis points up; ours down
  auto to_px = [&](const pointf& p) { return Eigen::Vector2d(p.x - bb.LL.x, bb.UR.y - p.y); };

  out.centres.resize(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    Agnode_t* n = agnode(g, const_cast<char*>(("n" + std::to_string(i)).c_str()), 0);
    if (n != nullptr) out.centres[i] = to_px(ND_coord(n));
  }
  out.splines.resize(edges.size());
  out.label_centres.resize(edges.size(), Eigen::Vector2d::Zero());
  std::vector<Polyline> first_half(edges.size()), second_half(edges.size());
  for (Agnode_t* n = agfstnode(g); n != nullptr; n = agnxtnode(g, n)) {
    for (Agedge_t* e = agfstout(g, n); e != nullptr; e = agnxtout(g, e)) {
      const char* id = agget(e, const_cast<char*>("id"));
      if (id == nullptr || id[0] != 'e') continue;  // the rows' invisible edges
      std::size_t used = 0;
      const std::size_t k = std::stoul(id + 1, &used);
      if (k >= edges.size()) continue;
      const char part = id[1 + used];  // 0, or 'a' / 'b' for the halves of a flat labelled edge
      Polyline pts;
      if (ED_spl(e) != nullptr && ED_spl(e)->size > 0) {
        const bezier& bz = ED_spl(e)->list[0];
        for (int j = 0; j < bz.size; ++j) pts.push_back(to_px(bz.list[j]));
      }
      // dot may store a flat or back edge from head to tail: orient it tail to head
      const Eigen::Vector2d tail = to_px(ND_coord(agtail(e)));
      if (!pts.empty() && (pts.back() - tail).norm() < (pts.front() - tail).norm())
        pts.assign(pts.rbegin(), pts.rend());
      if (part == 'a') {
        first_half[k] = std::move(pts);
      } else if (part == 'b') {
        second_half[k] = std::move(pts);
        out.label_centres[k] = to_px(ND_coord(agtail(e)));  // the label node
      } else {
        out.splines[k] = std::move(pts);
        if (ED_label(e) != nullptr) out.label_centres[k] = to_px(ED_label(e)->pos);
      }
    }
  }
  // a flat labelled edge: its two halves joined by a straight piece through the label's box
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (first_half[k].empty() || second_half[k].empty()) continue;
    Polyline joined = first_half[k];
    const Eigen::Vector2d a = joined.back(), b = second_half[k].front();
    joined.push_back(a + (b - a) / 3);
    joined.push_back(a + 2 * (b - a) / 3);
    joined.insert(joined.end(), second_half[k].begin(), second_half[k].end());
    out.splines[k] = std::move(joined);
  }
  char* text = nullptr;
  unsigned int length = 0;
  if (gvRenderData(gvc.get(), g, "dot", &text, &length) == 0 && text != nullptr) {
    out.dot.assign(text, length);
  }
  if (text != nullptr) gvFreeRenderData(text);
  gvFreeLayout(gvc.get(), g);
  agclose(g);
  return out;
}

}  // namespace pcsg::render
