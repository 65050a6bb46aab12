#pragma once
// Two graphs of one scene compared by their contact formations, witness poses and state
// numbers aside: the CFs and LN links one has that the other lacks, and how many states repeat
// a CF (two CF-connected regions of one CF, or one region found twice). Used by `pcsg sweep`
// to tell how a run at a coarser resolution differs from the finest run.
#include <string>
#include <vector>

#include "engine/generator/graph.h"
#include "engine/geometry/scene_geometry.h"

namespace pcsg::app {

struct GraphSignature {
  std::vector<std::string> states;  // the CF of every state, sorted, with repeats
  std::vector<std::string> links;   // every LN link as "CF -> CF", sorted, without repeats
  // The distinct CFs, sorted; and how many states repeat one (states - distinct CFs).
  std::vector<std::string> cfs() const;
  int repeats() const { return static_cast<int>(states.size() - cfs().size()); }
};

GraphSignature graph_signature(const StateGraph& graph, const SceneGeometry& scene);

struct GraphDiff {
  std::vector<std::string> cfs_added, cfs_missing;  // distinct CFs, against the reference
  std::vector<std::string> links_added, links_missing;
  int repeats = 0, reference_repeats = 0;
  // Same CFs and links (repeated states aside: they are reported, not compared).
  bool same_cfs_and_links() const {
    return cfs_added.empty() && cfs_missing.empty() && links_added.empty() && links_missing.empty();
  }
  bool same() const { return same_cfs_and_links() && repeats == reference_repeats; }
  // "same", or e.g. "-2 CFs, +1 link, 3 repeats (ref 4)"
  std::string summary() const;
};

GraphDiff diff_graphs(const GraphSignature& got, const GraphSignature& reference);

}  // namespace pcsg::app
