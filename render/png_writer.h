#pragma once
// A fast PNG writer for long image sequences (the frames of transition motions): zlib at a low
// compression level with one cheap row filter, ~5x faster than stb's encoder behind write_png
// (image.h), whose per-row filter search and own deflate take ~50 ms for a 640x600 frame on the
// build machine, for files ~20% larger. Like write_png, the bytes depend only on the pixels.
#include <string>

#include "render/image.h"

namespace pcsg::render {

// Writes an RGBA PNG; throws pcsg::Error naming the path when it cannot.
void write_png_fast(const Image& image, const std::string& path);

}  // namespace pcsg::render
