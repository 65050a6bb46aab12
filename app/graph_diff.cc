#include "app/graph_diff.h"

#include <algorithm>
#include <iterator>

namespace pcsg::app {
namespace {

std::vector<std::string> minus(const std::vector<std::string>& a,
                               const std::vector<std::string>& b) {
  std::vector<std::string> out;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

std::string count_text(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::vector<std::string> GraphSignature::cfs() const {
  std::vector<std::string> out = states;  // sorted already
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

GraphSignature graph_signature(const StateGraph& graph, const SceneGeometry& scene) {
  GraphSignature s;
  for (const State& st : graph.states) s.states.push_back(st.cf.str(scene));
  for (const Link& l : graph.links)
    if (l.kind == LinkKind::LN)
      s.links.push_back(graph.states[l.from].cf.str(scene) + " -> " +
                        graph.states[l.to].cf.str(scene));
  std::sort(s.states.begin(), s.states.end());
  std::sort(s.links.begin(), s.links.end());
  s.links.erase(std::unique(s.links.begin(), s.links.end()), s.links.end());
  return s;
}

GraphDiff diff_graphs(const GraphSignature& got, const GraphSignature& reference) {
  GraphDiff d;
  const std::vector<std::string> a = got.cfs(), b = reference.cfs();
  d.cfs_added = minus(a, b);
  d.cfs_missing = minus(b, a);
  d.links_added = minus(got.links, reference.links);
  d.links_missing = minus(reference.links, got.links);
  d.repeats = got.repeats();
  d.reference_repeats = reference.repeats();
  return d;
}

std::string GraphDiff::summary() const {
  if (same()) return "same";
  std::string out;
  auto part = [&](const std::string& text) { out += (out.empty() ? "" : ", ") + text; };
  auto counted = [&](const std::vector<std::string>& v, char sign, const char* one,
                     const char* many) {
    if (!v.empty()) part(sign + count_text(v.size(), one, many));
  };
  counted(cfs_added, '+', "CF", "CFs");
  counted(cfs_missing, '-', "CF", "CFs");
  counted(links_added, '+', "link", "links");
  counted(links_missing, '-', "link", "links");
  if (same_cfs_and_links()) part("same CFs and links");
  if (repeats != reference_repeats)
    part(std::to_string(repeats) + " repeats (ref " + std::to_string(reference_repeats) + ")");
  return out;
}

}  // namespace pcsg::app
