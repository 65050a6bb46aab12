#pragma once
// An 8-bit RGBA image, rows from top to bottom (the PNG order; GL's bottom-up rows are flipped
// once, when pixels are read back), and its PNG file I/O.
#include <cstdint>
#include <string>
#include <vector>

namespace pcsg::render {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, row 0 = top

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}
  bool empty() const { return width == 0 || height == 0; }
  std::uint8_t* pixel(int x, int y) { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
  const std::uint8_t* pixel(int x, int y) const {
    return &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
  }
  bool operator==(const Image& o) const {
    return width == o.width && height == o.height && rgba == o.rgba;
  }
};

// Writes a PNG (RGBA, 8 bits per channel); throws pcsg::Error naming the path on failure.
// The bytes depend only on the pixels (stb's deflate is deterministic).
void write_png(const Image& image, const std::string& path);
// Reads any PNG as RGBA; throws pcsg::Error naming the path when it cannot be read.
Image read_png(const std::string& path);

}  // namespace pcsg::render
