#pragma once
// A small antialiased rasteriser for charts (`pcsg sweep`'s plot): lines, markers, rectangles
// and text on an RGBA image. Text uses the renderer's embedded label font (DejaVu Sans, through
// stb_truetype), or stb's built-in bitmap font when none was embedded. Needs the renderer's
// image type and PNG writer, so it is compiled only with PCSG_WITH_RENDER.
#ifdef PCSG_WITH_RENDER
#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "render/image.h"

namespace pcsg::app {

using Rgb = std::array<std::uint8_t, 3>;

enum class Marker { Circle, Square, Triangle, Diamond };
enum class Align { Left, Center, Right };

class PlotCanvas {
 public:
  PlotCanvas(int width, int height, Rgb background);
  ~PlotCanvas();
  PlotCanvas(const PlotCanvas&) = delete;
  PlotCanvas& operator=(const PlotCanvas&) = delete;

  // A segment of the given width (pixels), with round ends; `dash` > 0 draws dashes of that
  // length with gaps of the same length.
  void line(double x0, double y0, double x1, double y1, double width, Rgb color, double dash = 0);
  void fill_rect(double x0, double y0, double x1, double y1, Rgb color);
  void stroke_rect(double x0, double y0, double x1, double y1, double width, Rgb color);
  // A marker of the given radius (pixels) centred at (x, y); hollow ones are outlined.
  void marker(double x, double y, Marker shape, double radius, Rgb color, bool hollow = false);
  // Text of height `px` (cap height plus descender, pixels) with its baseline at y, aligned at
  // x; `vertical` turns it 90 degrees counterclockwise (read bottom to top), x then being the
  // baseline and y the alignment point.
  void text(double x, double y, const std::string& s, double px, Rgb color,
            Align align = Align::Left, bool vertical = false);
  double text_width(const std::string& s, double px) const;

  const render::Image& image() const { return image_; }

 private:
  // Blends `color` into pixel (x, y) with coverage a in [0, 1].
  void blend(int x, int y, Rgb color, double a);
  struct Font;
  render::Image image_;
  std::unique_ptr<Font> font_;
};

}  // namespace pcsg::app
#endif  // PCSG_WITH_RENDER
