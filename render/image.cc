#include "render/image.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <cstring>

#include "engine/core/error.h"

namespace pcsg::render {

void write_png(const Image& image, const std::string& path) {
  if (image.empty() ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw Error("write_png: image for '" + path + "' is empty or inconsistent (" +
                std::to_string(image.width) + "x" + std::to_string(image.height) + ", " +
                std::to_string(image.rgba.size()) + " bytes)");
  }
  // Rows are already top-first: no flip on write (stbi_flip_vertically_on_write stays 0).
  const int stride = image.width * 4;
  if (stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), stride) == 0) {
    throw Error("cannot write PNG '" + path + "' (does its folder exist and is it writable?)");
  }
}

Image read_png(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (data == nullptr) {
    throw Error("cannot read PNG '" + path + "': " + stbi_failure_reason());
  }
  Image image(w, h);
  std::memcpy(image.rgba.data(), data, image.rgba.size());
  stbi_image_free(data);
  return image;
}

}  // namespace pcsg::render
