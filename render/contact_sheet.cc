#include "render/contact_sheet.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "render/canvas.h"
#include "render/palette.h"

namespace pcsg::render {

namespace {

// Frame widths in pixels: a hairline around every picture, thicker to single one out.
constexpr double kFrame = 1.5, kEmphasisedFrame = 3.5, kWarningFrame = 4;
// Light grey of ordinary frames: a picture's own white background still reads as bounded.
constexpr Rgb kFrameColour{0.72f, 0.73f, 0.76f};
// Space between a picture and its caption, and between caption lines, in caption heights.
constexpr double kCaptionGap = 0.35, kLineSpacing = 1.25;

}  // namespace

Image compose_contact_sheet(const std::vector<SheetCell>& cells, const SheetOptions& o,
                            const TextPainter& text) {
  if (cells.empty()) throw Error("compose_contact_sheet: no pictures");
  const int n = static_cast<int>(cells.size());
  const int cell_w = o.cell_width > 0 ? o.cell_width : cells.front().picture.width;
  std::vector<Image> pictures;
  std::size_t max_lines = 0;
  for (const SheetCell& c : cells) {
    const int h = std::max(1, static_cast<int>(std::lround(static_cast<double>(c.picture.height) *
                                                          cell_w / std::max(1, c.picture.width))));
    pictures.push_back(resized(c.picture, cell_w, h));
    max_lines = std::max(max_lines, c.caption.size());
  }
  const double line = text.line_height(o.caption_px) * kLineSpacing;
  const double caption_h =
      max_lines > 0 ? kCaptionGap * text.line_height(o.caption_px) + line * max_lines : 0;
  // columns: about square, given the typical cell's aspect
  int columns = o.columns;
  if (columns <= 0) {
    const double cell_h = pictures.front().height + caption_h + o.gap;
    columns = std::max(1, static_cast<int>(std::lround(std::sqrt(n * cell_h / (cell_w + o.gap)))));
  }
  columns = std::min(columns, n);
  const int rows = (n + columns - 1) / columns;
  std::vector<int> row_h(rows, 0);
  for (int i = 0; i < n; ++i)
    row_h[i / columns] = std::max(row_h[i / columns],
                                  pictures[i].height + static_cast<int>(std::ceil(caption_h)));

  double header = 0;
  if (!o.title.empty()) header += text.line_height(o.title_px) * 1.3;
  if (!o.subtitle.empty()) header += text.line_height(o.subtitle_px) * 1.3;
  if (!o.legend.empty()) header += text.line_height(o.subtitle_px) * 1.3;
  if (header > 0) header += o.gap;
  int content_h = 0;
  for (int h : row_h) content_h += h;
  const int width = 2 * o.margin + columns * cell_w + (columns - 1) * o.gap;
  const int height = static_cast<int>(2 * o.margin + header + content_h + (rows - 1) * o.gap);

  Image sheet(width, height);
  Canvas canvas(sheet);
  canvas.fill(palette::kBackground);
  double y = o.margin;
  if (!o.title.empty()) {
    text.draw(sheet, o.margin, y, text.fit(o.title, o.title_px, width - 2.0 * o.margin),
              o.title_px, palette::kText);
    y += text.line_height(o.title_px) * 1.3;
  }
  if (!o.subtitle.empty()) {
    text.draw(sheet, o.margin, y, text.fit(o.subtitle, o.subtitle_px, width - 2.0 * o.margin),
              o.subtitle_px, palette::kLeader);
    y += text.line_height(o.subtitle_px) * 1.3;
  }
  if (!o.legend.empty()) {
    const double px = o.subtitle_px;
    double x = o.margin;
    for (const SheetLegendEntry& e : o.legend) {
      canvas.stroke_circle({x + 0.45 * px, y + 0.5 * text.line_height(px)}, 0.4 * px, e.colour,
                           0.15 * px);
      x += 1.2 * px;
      x += text.draw(sheet, x, y, e.text, px, e.colour) + 1.2 * px;
    }
    y += text.line_height(px) * 1.3;
  }
  if (header > 0) y += o.gap;

  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns && r * columns + c < n; ++c) {
      const int i = r * columns + c;
      const SheetCell& cell = cells[i];
      const int x = o.margin + c * (cell_w + o.gap);
      const int top = static_cast<int>(y);
      canvas.blit(pictures[i], x, top);
      const double fw = cell.warning ? kWarningFrame : cell.emphasised ? kEmphasisedFrame : kFrame;
      const Rgb fc = cell.warning ? palette::kWarning : cell.emphasised ? palette::kEdge : kFrameColour;
      canvas.stroke_rect(x, top, x + cell_w, top + pictures[i].height, fc, fw);
      double ty = top + pictures[i].height + kCaptionGap * text.line_height(o.caption_px);
      for (std::size_t k = 0; k < cell.caption.size(); ++k) {
        const Rgb colour = k == 0 ? (cell.warning ? palette::kWarning : palette::kText)
                                  : palette::kLeader;
        text.draw(sheet, x, ty, text.fit(cell.caption[k], o.caption_px, cell_w), o.caption_px,
                  colour);
        ty += line;
      }
    }
    y += row_h[r] + o.gap;
  }
  return sheet;
}

}  // namespace pcsg::render
