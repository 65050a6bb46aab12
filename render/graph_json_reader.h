#pragma once
// Reads a graph written by graph_to_json (engine/generator/graph_io.h) back into a StateGraph,
// to draw a stored graph (`pcsg diagram`, the golden tests) or to replay its candidates
// without generating it again. Contacts keep what the file has (elements, type, point, normal,
// gap); a replay that needs their exact local data re-detects them at the witness pose.
#include <string>

#include "engine/generator/graph.h"

namespace pcsg::render {

// Throws pcsg::Error naming the file and the offending entry when the file is missing or
// malformed or names an element the scene does not have.
StateGraph read_graph_json(const std::string& path, const SceneGeometry& scene);

}  // namespace pcsg::render
