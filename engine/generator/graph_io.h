#pragma once
// The graph as JSON (graph.json) and as Graphviz DOT (graph.dot). Byte-identical output for
// the same graph: fixed key order, doubles printed with 17 significant digits, and no timing
// in the JSON unless asked for.
#include <string>

#include "engine/generator/graph.h"

namespace pcsg {

struct GraphJsonOptions {
  // Run-dependent figures (seconds, in all and by phase) make the JSON differ between runs;
  // determinism checks leave them out.
  bool include_timing = true;
};

std::string graph_to_json(const StateGraph& graph, const SceneGeometry& scene,
                          const GraphJsonOptions& options = {});
// Layers by cardinality (the seeds' on top), LN links solid, GN links dashed.
std::string graph_to_dot(const StateGraph& graph, const SceneGeometry& scene);

}  // namespace pcsg
