#pragma once
// Shared by the generator tests: loading the shipped scenes, a graph's comparable signature.
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "engine/generator/generator.h"
#include "engine/geometry/scene_geometry.h"
#include "engine/scene/scene.h"

namespace pcsg::testing {

inline std::string scene_path(const std::string& name) {
  return std::string(PCSG_SOURCE_DIR) + "/scenes/" + name;
}

// A graph's structure independent of witness poses and state numbering: the distinct CFs of
// its states and the distinct CF pairs of its LN links. Distinct, because two witnesses of one
// CF that pcsg could not yet prove CF-connected stay two states (an open defect recorded in
// docs/paper-comparison.md), and how many such duplicates appear depends on the witnesses.
struct GraphSignature {
  std::vector<std::string> states;
  std::vector<std::string> links;
  bool operator==(const GraphSignature& o) const {
    return states == o.states && links == o.links;
  }
};

inline GraphSignature signature(const StateGraph& g, const SceneGeometry& scene) {
  GraphSignature s;
  for (const State& st : g.states) s.states.push_back(st.cf.str(scene));
  for (const Link& l : g.links)
    if (l.kind == LinkKind::LN)
      s.links.push_back(g.states[l.from].cf.str(scene) + " -> " + g.states[l.to].cf.str(scene));
  std::sort(s.states.begin(), s.states.end());
  s.states.erase(std::unique(s.states.begin(), s.states.end()), s.states.end());
  std::sort(s.links.begin(), s.links.end());
  s.links.erase(std::unique(s.links.begin(), s.links.end()), s.links.end());
  return s;
}

inline std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += "  " + s + "\n";
  return out;
}

}  // namespace pcsg::testing
