#include "render/diagram.h"

#include <algorithm>
#include <cmath>

#include "render/canvas.h"
#include "render/graph_layout.h"

namespace pcsg::render {

namespace {

// Inside a node's frame: padding around the picture and the caption, in pixels.
constexpr double kPad = 8;
constexpr double kFrame = 1.5, kEmphasisedFrame = 3.5;
constexpr Rgb kFrameColour{0.62f, 0.63f, 0.67f};
// Caption lines are this many caption heights apart.
constexpr double kLineSpacing = 1.25;
// Dashes of dashed links, in link widths: long enough to read as dashes at any zoom.
constexpr double kDashOn = 4, kDashOff = 3;
// Padding of an edge label's white box, in label heights.
constexpr double kLabelPad = 0.25;
// Length of a legend's line sample, in arrow lengths.
constexpr double kLegendSample = 4;

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

struct NodeBox {
  double width = 0, height = 0;
};

NodeBox node_box(const DiagramNode& n, const DiagramOptions& o, const TextPainter& text) {
  double w = n.picture.width;
  for (const std::string& line : n.caption) w = std::max(w, text.width(line, o.caption_px));
  const double caption = n.caption.size() * text.line_height(o.caption_px) * kLineSpacing;
  return {w + 2 * kPad, n.picture.height + caption + 2 * kPad + (n.caption.empty() ? 0 : kPad)};
}

void draw_link(Canvas& canvas, const Polyline& curve, const DiagramEdge& e,
               const DiagramOptions& o) {
  if (curve.size() < 2) return;
  Polyline line = curve;
  if (e.head) line = trim_end(line, 0.8 * o.arrow_length);
  if (e.tail) {
    Polyline reversed(line.rbegin(), line.rend());
    reversed = trim_end(reversed, 0.8 * o.arrow_length);
    line.assign(reversed.rbegin(), reversed.rend());
  }
  const Dash dash = e.style == LinkStyle::Dashed
                        ? Dash{kDashOn * o.link_width, kDashOff * o.link_width}
                        : Dash{};
  canvas.stroke(line, e.colour, o.link_width, dash);
  // arrowheads point along the curve's last (first) stretch of about one head length
  auto direction_at_end = [&](const Polyline& c) {
    const Eigen::Vector2d tip = c.back();
    for (std::size_t k = c.size() - 1; k-- > 0;) {
      if ((tip - c[k]).norm() >= o.arrow_length || k == 0) return Eigen::Vector2d(tip - c[k]);
    }
    return Eigen::Vector2d(tip - c.front());
  };
  const double outline = 0.7 * o.link_width;
  if (e.head)
    canvas.arrowhead(curve.back(), direction_at_end(curve), o.arrow_length, e.colour, e.head_open,
                     outline);
  if (e.tail) {
    const Polyline reversed(curve.rbegin(), curve.rend());
    canvas.arrowhead(reversed.back(), direction_at_end(reversed), o.arrow_length, e.colour,
                     e.tail_open, outline);
  }
}

}  // namespace

Diagram draw_diagram(const std::vector<DiagramNode>& nodes, const std::vector<DiagramEdge>& edges,
                     const DiagramOptions& o, const TextPainter& text) {
  // 1. layout: boxes of the nodes' sizes, labels of their text's size
  std::vector<NodeBox> boxes;
  std::vector<LayoutNode> lnodes;
  for (const DiagramNode& n : nodes) {
    boxes.push_back(node_box(n, o, text));
    lnodes.push_back({boxes.back().width, boxes.back().height, n.row});
  }
  const double line_h = text.line_height(o.label_px), pad = kLabelPad * line_h;
  std::vector<LayoutEdge> ledges;
  std::vector<std::vector<std::string>> label_lines;
  for (const DiagramEdge& e : edges) {
    LayoutEdge le{e.from, e.to, 0, 0};
    label_lines.push_back(split_lines(e.label));
    for (const std::string& line : label_lines.back())
      le.label_width = std::max(le.label_width, text.width(line, o.label_px) + 2 * pad);
    if (!label_lines.back().empty()) le.label_height = line_h * label_lines.back().size() + 2 * pad;
    ledges.push_back(le);
  }
  LayoutOptions lo;
  lo.node_gap = o.node_gap;
  lo.rank_gap = o.rank_gap;
  const GraphLayout layout = layout_graph(lnodes, ledges, lo);

  // 2. the canvas: title above, legend below
  double header = 0;
  if (!o.title.empty()) header += text.line_height(o.title_px) * 1.35;
  if (!o.subtitle.empty()) header += text.line_height(o.subtitle_px) * 1.35;
  if (header > 0) header += 0.5 * o.rank_gap;
  const double legend_line = std::max(text.line_height(o.caption_px), o.arrow_length) * 1.5;
  const double legend = o.legend.empty() ? 0 : 0.5 * o.rank_gap + legend_line * o.legend.size();
  double legend_w = 0;
  for (const LegendItem& l : o.legend)
    legend_w = std::max(legend_w, kLegendSample * o.arrow_length + 12 + text.width(l.text, o.caption_px));
  double title_w = std::max(text.width(o.title, o.title_px), text.width(o.subtitle, o.subtitle_px));
  const double content_w = std::max({layout.width, legend_w, title_w});
  const int width = static_cast<int>(std::ceil(content_w + 2 * o.margin));
  const int height = static_cast<int>(std::ceil(layout.height + header + legend + 2 * o.margin));
  Diagram out;
  out.dot = layout.dot;
  out.image = Image(width, height);
  Canvas canvas(out.image);
  canvas.fill(palette::kBackground);
  double y = o.margin;
  if (!o.title.empty()) {
    text.draw(out.image, o.margin, y, o.title, o.title_px, palette::kText);
    y += text.line_height(o.title_px) * 1.35;
  }
  if (!o.subtitle.empty()) text.draw(out.image, o.margin, y, o.subtitle, o.subtitle_px, palette::kLeader);
  // the graph, centred horizontally
  const Eigen::Vector2d origin(o.margin + 0.5 * (content_w - layout.width), o.margin + header);

  // 3. links under the nodes, then the nodes, then the labels on top
  for (std::size_t k = 0; k < edges.size(); ++k) {
    Polyline curve = flatten_bezier(layout.splines[k]);
    for (auto& p : curve) p += origin;
    draw_link(canvas, curve, edges[k], o);
  }
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const DiagramNode& n = nodes[i];
    const Eigen::Vector2d c = layout.centres[i] + origin;
    const double x0 = std::round(c.x() - 0.5 * boxes[i].width);
    const double y0 = std::round(c.y() - 0.5 * boxes[i].height);
    canvas.fill_rect(x0, y0, x0 + boxes[i].width, y0 + boxes[i].height, palette::kBackground);
    const double fw = n.emphasised ? kEmphasisedFrame : kFrame;
    canvas.stroke_rect(x0, y0, x0 + boxes[i].width, y0 + boxes[i].height,
                       n.emphasised ? palette::kEdge : kFrameColour, fw);
    const int px = static_cast<int>(x0 + 0.5 * (boxes[i].width - n.picture.width));
    canvas.blit(n.picture, px, static_cast<int>(y0 + kPad));
    double ty = y0 + kPad + n.picture.height + kPad;
    for (std::size_t k = 0; k < n.caption.size(); ++k) {
      const double tw = text.width(n.caption[k], o.caption_px);
      text.draw(out.image, x0 + 0.5 * (boxes[i].width - tw), ty, n.caption[k], o.caption_px,
                k == 0 ? palette::kText : palette::kLeader);
      ty += text.line_height(o.caption_px) * kLineSpacing;
    }
  }
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (edges[k].label.empty()) continue;
    const Eigen::Vector2d c = layout.label_centres[k] + origin;
    const double w = ledges[k].label_width, h = ledges[k].label_height;
    canvas.fill_rect(c.x() - 0.5 * w, c.y() - 0.5 * h, c.x() + 0.5 * w, c.y() + 0.5 * h,
                     palette::kBackground);
    double ty = c.y() - 0.5 * h + pad;
    for (const std::string& line : label_lines[k]) {
      text.draw(out.image, c.x() - 0.5 * w + pad, ty, line, o.label_px, edges[k].colour);
      ty += line_h;
    }
  }

  // 4. legend: a line sample and its meaning per item
  double ly = o.margin + header + layout.height + 0.5 * o.rank_gap;
  for (const LegendItem& l : o.legend) {
    const double mid = ly + 0.5 * legend_line;
    DiagramEdge sample;
    sample.style = l.style;
    sample.colour = l.colour;
    sample.head_open = l.open;
    draw_link(canvas, {{o.margin + 0.0, mid}, {o.margin + kLegendSample * o.arrow_length, mid}},
              sample, o);
    text.draw(out.image, o.margin + kLegendSample * o.arrow_length + 12,
              mid - 0.5 * text.line_height(o.caption_px), l.text, o.caption_px, palette::kText);
    ly += legend_line;
  }
  return out;
}

}  // namespace pcsg::render
