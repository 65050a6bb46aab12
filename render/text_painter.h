#pragma once
// Text on an RGBA image on the CPU, for captions and headers of composed figures (diagram
// nodes, contact sheets, banners over frames): the same DejaVu Sans the renderer's labels use
// (embedded at build time), rasterised by stb_truetype with antialiasing and quarter-pixel
// horizontal placement. Without the embedded font, stb_easy_font's built-in strokes are used,
// so text never disappears (only its looks change, and golden tests skip).
// Not thread-safe (a glyph cache): one painter per thread.
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "render/image.h"
#include "render/palette.h"

namespace pcsg::render {

class TextPainter {
 public:
  TextPainter();
  ~TextPainter();
  TextPainter(const TextPainter&) = delete;
  TextPainter& operator=(const TextPainter&) = delete;

  // Width in pixels of one line of UTF-8 text at a font size of `px` (the line height).
  double width(std::string_view text, double px) const;
  // Height of one line (ascent + descent) at size `px`.
  double line_height(double px) const;
  // Draws one line with the top of its line box at y; returns its width.
  double draw(Image& image, double x, double y, std::string_view text, double px,
              const Rgb& colour) const;
  // The text, cut with an ellipsis so that it is at most `max_width` wide.
  std::string fit(std::string_view text, double px, double max_width) const;
  bool has_truetype() const { return font_ != nullptr; }

 private:
  struct Font;
  struct Glyph {
    int width = 0, height = 0, x0 = 0, y0 = 0;  // offset of the bitmap from the pen position
    std::vector<unsigned char> alpha;
  };
  const Glyph& glyph(int index, double px, int quarter) const;
  double draw_fallback(Image& image, double x, double y, std::string_view text, double px,
                       const Rgb& colour) const;

  std::unique_ptr<Font> font_;
  // (glyph index, size in 1/64 px, quarter-pixel shift) -> bitmap
  mutable std::map<std::tuple<int, int, int>, Glyph> cache_;
};

// Code points of a UTF-8 string (malformed bytes become U+FFFD).
std::vector<char32_t> decode_utf8(std::string_view text);

}  // namespace pcsg::render
