#pragma once
// A small single-sample framebuffer with one integer per pixel, for the element-id pass that
// tells which face or edge is visible where (label anchors). A quarter of the image's linear
// resolution is plenty to find where an element shows, and it costs 1/16 of the pixels.
#include <cstdint>
#include <vector>

#include "render/gl_handle.h"

namespace pcsg::render {

// Ids per pixel, rows top first (like Image).
struct IdImage {
  int width = 0, height = 0;
  double scale = 1;  // image pixels per id pixel
  std::vector<std::int32_t> ids;
  std::int32_t at(int x, int y) const { return ids[static_cast<std::size_t>(y) * width + x]; }
};

class IdTarget {
 public:
  void allocate(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }
  // Binds the framebuffer and clears ids to 0 (background) and depth to far.
  void begin();
  IdImage read(double scale);

 private:
  int width_ = 0, height_ = 0;
  GlHandle fbo_, ids_, depth_;
};

}  // namespace pcsg::render
