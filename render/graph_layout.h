#pragma once
// Layered layout of a small directed graph by Graphviz's dot (libgvc): nodes are boxes of
// given pixel sizes in given rows, edges come back as cubic Bezier splines that end on the
// node boxes, edge labels as boxes of given sizes. Dot orders each row to reduce crossings and
// routes the edges; we only choose the rows, and draw (render/diagram.h), so the pictures look
// like the rest of pcsg.
//
// Two traps of Graphviz 2.42/2.43 avoided here: a label on an edge within a row ("flat" edge)
// corrupts dot's memory (a double free in gvFreeLayout), so such a label becomes a node of the
// label's size between the edge's ends, in the same row; and Graphviz keeps global state, so
// layouts are serialised by a process-wide mutex.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "render/canvas.h"

namespace pcsg::render {

struct LayoutNode {
  double width = 100, height = 100;  // pixels
  // Nodes with the same row >= 0 share a rank, rows from the top in increasing order (kept
  // even where no edge joins two rows). Nodes with row -1 are ranked by dot.
  int row = -1;
};

struct LayoutEdge {
  int from = -1, to = -1;  // dot ranks `from` above `to` (unless rows say otherwise)
  double label_width = 0, label_height = 0;  // pixels; 0: no label
};

struct LayoutOptions {
  double node_gap = 40;  // pixels between neighbours of one rank (dot's nodesep)
  double rank_gap = 70;  // pixels between ranks (dot's ranksep)
  std::string name = "pcsg";
};

struct GraphLayout {
  double width = 0, height = 0;                // bounding box of the drawing, pixels
  std::vector<Eigen::Vector2d> centres;        // per node, pixels, y down
  std::vector<Polyline> splines;               // per edge: 3n+1 Bezier control points,
                                               // from `from` to `to`
  std::vector<Eigen::Vector2d> label_centres;  // per edge (meaningful when it has a label)
  std::string dot;  // the input graph with dot's positions ("pos", "bb"): for other tools
};

// Throws pcsg::Error when Graphviz cannot lay the graph out (e.g. its dot plugin is missing).
GraphLayout layout_graph(const std::vector<LayoutNode>& nodes,
                         const std::vector<LayoutEdge>& edges,
                         const LayoutOptions& options = {});

}  // namespace pcsg::render
