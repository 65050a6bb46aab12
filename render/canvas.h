#pragma once
// 2D drawing on an RGBA image on the CPU, for what is composed after the 3D frames are read
// back: graph diagrams (thumbnails, links as splines with arrowheads, dashed GN links), contact
// sheets, contact-role rings and banners over frames. Antialiased by exact coverage of
// distance fields (strokes, discs) and of convex polygons, so the output is a pure function of
// the inputs: no GL, no threads, byte-identical across machines.
//
// Coordinates are pixels, x right, y down, with pixel (i, j) covering [i, i+1) x [j, j+1):
// a one-pixel line through the middle of row j is drawn at y = j + 0.5.
#include <Eigen/Core>
#include <vector>

#include "render/image.h"
#include "render/palette.h"

namespace pcsg::render {

using Polyline = std::vector<Eigen::Vector2d>;

// Dash pattern of a stroke in pixels; `on` = 0 means solid.
struct Dash {
  double on = 0, off = 0;
};

class Canvas {
 public:
  // Draws into `image`, which must outlive the canvas.
  explicit Canvas(Image& image) : image_(image) {}

  int width() const { return image_.width; }
  int height() const { return image_.height; }

  void fill(const Rgb& colour);
  // Axis-aligned rectangle [x0, x1) x [y0, y1), partially covered pixels blended.
  void fill_rect(double x0, double y0, double x1, double y1, const Rgb& colour, float alpha = 1);
  // The outline of that rectangle, `width` pixels wide, inside it.
  void stroke_rect(double x0, double y0, double x1, double y1, const Rgb& colour, double width);
  // A polyline `width` pixels wide with round joints and caps; dashed along its length when
  // `dash.on` > 0 (the pattern runs on across vertices).
  void stroke(const Polyline& points, const Rgb& colour, double width, const Dash& dash = {});
  void fill_disc(const Eigen::Vector2d& centre, double radius, const Rgb& colour, float alpha = 1);
  void stroke_circle(const Eigen::Vector2d& centre, double radius, const Rgb& colour,
                     double width);
  // A convex polygon (either orientation).
  void fill_convex(const Polyline& polygon, const Rgb& colour, float alpha = 1);
  // An arrowhead with its tip at `tip`, pointing along `direction`, `length` long; filled, or
  // (open) its outline `outline` pixels wide on white.
  void arrowhead(const Eigen::Vector2d& tip, const Eigen::Vector2d& direction, double length,
                 const Rgb& colour, bool open = false, double outline = 2);
  // Copies `source` with its top-left corner at (x, y), clipped to the canvas.
  void blit(const Image& source, int x, int y);
  // Blends one pixel with the colour at coverage `alpha` in [0, 1] (clipped).
  void blend(int x, int y, const Rgb& colour, float alpha);

 private:
  void stroke_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Rgb& colour,
                      double width);
  Image& image_;
};

// Points of a piecewise cubic Bezier curve given by 3n+1 control points (Graphviz's spline
// format), each piece flattened into `segments` straight segments.
Polyline flatten_bezier(const Polyline& control, int segments = 16);

// Length of a polyline.
double polyline_length(const Polyline& points);

// The polyline without its last `length` pixels (so that an arrowhead's tip lands on the
// curve's end instead of under its stroke); a shorter polyline shrinks to its first point.
Polyline trim_end(const Polyline& points, double length);

// The pixels [x0, x1) x [y0, y1) that differ from `background` by more than `tolerance` levels
// in some channel; empty (x0 >= x1) for a blank image.
struct PixelBounds {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
};
PixelBounds content_bounds(const Image& image, const Rgb& background, int tolerance = 6);

// The part [x0, x0 + width) x [y0, y0 + height) of an image; outside pixels are `fill`.
Image cropped(const Image& image, int x0, int y0, int width, int height,
              const Rgb& fill = palette::kBackground);

// Resized copy with a box-filtered (area-averaging) downscale or bilinear upscale, via stb's
// resizer; deterministic.
Image resized(const Image& source, int width, int height);

}  // namespace pcsg::render
