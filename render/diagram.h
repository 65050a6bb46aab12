#pragma once
// A graph drawn as a diagram whose nodes are pictures (paper Fig. 6: the states of an LN graph
// as pictures with their CFs, links between neighbours). Graphviz's dot lays it out
// (render/graph_layout.h); pictures, captions, splines, arrowheads and labels are drawn here.
#include <string>
#include <vector>

#include "render/image.h"
#include "render/palette.h"
#include "render/text_painter.h"

namespace pcsg::render {

enum class LinkStyle { Solid, Dashed };

struct DiagramNode {
  Image picture;
  std::vector<std::string> caption;  // lines under the picture, the first darker
  int row = -1;                      // its row, 0 on top; -1: dot chooses
  bool emphasised = false;           // a thicker frame (the seed)
};

struct DiagramEdge {
  int from = -1, to = -1;  // dot places `from` above `to` unless they share a row
  LinkStyle style = LinkStyle::Solid;
  Rgb colour = palette::kEdge;
  bool head = true;   // arrowhead at `to`
  bool tail = false;  // arrowhead at `from`
  bool head_open = false, tail_open = false;  // drawn as outlines instead of filled
  std::string label;  // drawn on the link in a small font, lines split at '\n'; empty: none
};

struct LegendItem {
  LinkStyle style = LinkStyle::Solid;
  Rgb colour = palette::kEdge;
  std::string text;
  bool open = false;  // the sample's arrowhead as an outline
};

struct DiagramOptions {
  std::string title, subtitle;
  std::vector<LegendItem> legend;  // drawn under the graph
  double title_px = 28, subtitle_px = 19, caption_px = 18, label_px = 14;
  double link_width = 2.6, arrow_length = 15;
  double node_gap = 44, rank_gap = 80;  // between nodes of a row, between rows
  int margin = 28;
};

struct Diagram {
  Image image;
  std::string dot;  // the layout dot computed, with positions (Graphviz's "dot" output)
};

// Throws pcsg::Error when an edge names a missing node or Graphviz fails.
Diagram draw_diagram(const std::vector<DiagramNode>& nodes, const std::vector<DiagramEdge>& edges,
                     const DiagramOptions& options, const TextPainter& text);

}  // namespace pcsg::render
