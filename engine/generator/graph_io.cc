#include "engine/generator/graph_io.h"

#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

namespace pcsg {
namespace {

using nlohmann::ordered_json;

ordered_json vec(const Eigen::Vector3d& v) { return ordered_json::array({v.x(), v.y(), v.z()}); }

ordered_json cf_json(const ContactFormation& cf, const SceneGeometry& scene) {
  ordered_json arr = ordered_json::array();
  for (const PtcCount& e : cf.entries())
    arr.push_back({{"a", scene.A.element_name(e.a)},
                   {"b", scene.B.element_name(e.b)},
                   {"type", ptc_type_name(e.type)},
                   {"count", e.count}});
  return arr;
}

ordered_json pose_json(const Pose& pose) {
  const Pose p = pose.canonical();
  return {{"position", vec(p.position)},
          {"quaternion", ordered_json::array({p.quaternion.w(), p.quaternion.x(), p.quaternion.y(),
                                              p.quaternion.z()})}};
}

std::string dot_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string graph_to_json(const StateGraph& graph, const SceneGeometry& scene,
                          const GraphJsonOptions& options) {
  ordered_json j;
  j["scene"] = graph.scene;
  j["scene_file"] = scene.spec.path;
  j["length_scale"] = scene.tol.length_scale;
  ordered_json states = ordered_json::array();
  for (const State& s : graph.states) {
    ordered_json contacts = ordered_json::array();
    for (const PointContact& c : s.contacts)
      contacts.push_back({{"a", scene.A.element_name(c.a)},
                          {"b", scene.B.element_name(c.b)},
                          {"type", ptc_type_name(c.type)},
                          {"point", vec(c.point_B)},
                          {"normal", vec(c.normal_B)},
                          {"gap", c.gap}});
    states.push_back({{"id", s.id},
                      {"cf", cf_json(s.cf, scene)},
                      {"cf_text", s.cf.str(scene)},
                      {"card", s.cf.cardinality()},
                      {"pose", pose_json(s.pose)},
                      {"contacts", contacts},
                      {"seed", s.seed},
                      {"depth", s.depth}});
  }
  j["states"] = states;
  ordered_json links = ordered_json::array();
  for (const Link& l : graph.links)
    links.push_back({{"from", l.from},
                     {"to", l.to},
                     {"kind", l.kind == LinkKind::LN ? "LN" : "GN"},
                     {"motion", l.motion}});
  j["links"] = links;
  ordered_json cands = ordered_json::array();
  for (const Candidate& c : graph.candidates) {
    ordered_json cj = {{"from", c.from},
                       {"cf", cf_json(c.cf, scene)},
                       {"cf_text", c.cf.str(scene)},
                       {"feasible", c.feasible},
                       {"motion", c.motion},
                       {"attempts", c.attempts},
                       {"steps", c.steps}};
    if (!c.crossing.empty()) cj["crossing"] = c.crossing;
    if (c.start) cj["start"] = pose_json(*c.start);
    if (c.run.known())
      cj["run"] = {{"start", c.run.start}, {"plan", c.run.plan}, {"variant", c.run.variant}};
    if (c.feasible) cj["to"] = c.to;
    if (!c.feasible) cj["reason"] = c.reason;
    cands.push_back(cj);
  }
  j["candidates"] = cands;
  ordered_json stats = {{"states", graph.states.size()},
                        {"links", graph.links.size()},
                        {"candidates", graph.candidates.size()},
                        {"collision_queries", graph.stats.collision_queries},
                        {"pair_solves", graph.stats.pair_solves},
                        {"motion_steps", graph.stats.motion_steps}};
  ordered_json phases = ordered_json::object();
  for (const auto& [phase, queries] : graph.stats.queries_by_phase) phases[phase] = queries;
  stats["collision_queries_by_phase"] = phases;
  if (options.include_timing) {
    stats["seconds"] = graph.stats.seconds;
    ordered_json seconds = ordered_json::object();
    for (const auto& [phase, s] : graph.stats.seconds_by_phase) seconds[phase] = s;
    stats["seconds_by_phase"] = seconds;
  }
  j["stats"] = stats;
  return j.dump(2) + "\n";
}

std::string graph_to_dot(const StateGraph& graph, const SceneGeometry& scene) {
  std::string out = "digraph pcsg {\n  rankdir=TB;\n  node [shape=box, fontname=\"Helvetica\"];\n";
  out += "  label=\"" + dot_escape(graph.scene) + "\";\n";
  std::map<int, std::vector<int>, std::greater<int>> by_card;
  for (const State& s : graph.states) by_card[s.cf.cardinality()].push_back(s.id);
  for (const auto& [card, ids] : by_card) {
    out += "  { rank=same;";
    for (int id : ids) out += " s" + std::to_string(id) + ";";
    out += " }\n";
  }
  for (const State& s : graph.states) {
    out += "  s" + std::to_string(s.id) + " [label=\"" + std::to_string(s.id) + ": " +
           dot_escape(s.cf.str(scene)) + "\"" + (s.seed ? ", style=bold" : "") + "];\n";
  }
  // One edge per neighbouring pair: LN solid (toward lower cardinality), GN dashed.
  std::set<std::pair<int, int>> drawn;
  for (const Link& l : graph.links) {
    if (l.kind != LinkKind::LN) continue;
    const auto key = std::minmax(l.from, l.to);
    if (!drawn.insert(key).second) continue;
    const bool equal = graph.states[l.from].cf.cardinality() == graph.states[l.to].cf.cardinality();
    out += "  s" + std::to_string(l.from) + " -> s" + std::to_string(l.to) + " [label=\"" +
           dot_escape(l.motion) + "\"" + (equal ? ", dir=both" : "") + "];\n";
  }
  out += "}\n";
  return out;
}

}  // namespace pcsg
