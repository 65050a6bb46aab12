#pragma once
// A contact sheet: pictures in a grid, each framed, with caption lines below it, under a
// title. Serves the frames of one transition motion (one sheet per candidate) and the grid of
// valid states (paper Fig. 8).
#include <string>
#include <vector>

#include "render/image.h"
#include "render/palette.h"
#include "render/text_painter.h"

namespace pcsg::render {

struct SheetCell {
  Image picture;
  std::vector<std::string> caption;  // lines under the picture, the first darker
  bool warning = false;              // frame and first caption line in the warning colour
  bool emphasised = false;           // a thicker frame (e.g. the seed state)
};

// A legend entry under the subtitle: a ring of the colour, then the text.
struct SheetLegendEntry {
  std::string text;
  Rgb colour;
};

struct SheetOptions {
  int columns = 0;     // 0: chosen so that the sheet is about as wide as it is tall
  int cell_width = 0;  // pictures are scaled to this width (0: the first picture's)
  std::string title, subtitle;
  std::vector<SheetLegendEntry> legend;
  double title_px = 26, subtitle_px = 18, caption_px = 17;
  int gap = 16, margin = 24;
};

// Pictures of different sizes are scaled to the cell width keeping their aspect; rows take
// the height of their tallest cell. Throws pcsg::Error when there is no cell.
Image compose_contact_sheet(const std::vector<SheetCell>& cells, const SheetOptions& options,
                            const TextPainter& text);

}  // namespace pcsg::render
