#pragma once
// The diagram of a point-contact state graph (paper Fig. 6): every state as a picture with its
// CF, in rows by cardinality (the seeds' on top). LN links are solid with arrowheads toward the
// LN state (both ends when the cardinalities are equal, since each is then an LN of the
// other), labelled with their motion; the GN link back up, the reverse of an LN link of lower
// cardinality, is dashed. A large graph is drawn compact: one unlabelled curve per
// neighbouring pair, the GN link an open arrowhead at the curve's upper end.
#include <vector>

#include "engine/generator/graph.h"
#include "render/diagram.h"
#include "render/state_pictures.h"

namespace pcsg::render {

struct StateDiagramOptions {
  bool motion_labels = true;  // each LN link's motion ("slidingA+rotation", ...)
  // More neighbouring pairs than this: compact (dot's routing of hundreds of labelled and
  // doubled links makes diagrams many screens wide and unreadable).
  std::size_t max_detailed_pairs = 30;
  std::string title;          // default: the graph's scene name
};

// `pictures[i]` is the picture of graph.states[i]. Throws pcsg::Error when the counts differ.
Diagram draw_state_diagram(const StateGraph& graph, const SceneGeometry& scene,
                           const std::vector<Image>& pictures, const StateDiagramOptions& options,
                           const TextPainter& text);

}  // namespace pcsg::render
