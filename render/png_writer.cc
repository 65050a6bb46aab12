#include "render/png_writer.h"

#include <zlib.h>

#include <cstdio>
#include <memory>
#include <vector>

#include "engine/core/error.h"

namespace pcsg::render {

namespace {

// zlib level 2: most of the size reduction of the higher levels at a fraction of their time.
constexpr int kDeflateLevel = 2;
// PNG filter type 1 ("Sub"): each byte minus the one a pixel to its left, which flattens
// smooth shading and the white background to runs of zeros.
constexpr unsigned char kFilterSub = 1;

void put32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<unsigned char>(v >> s));
}

void chunk(std::vector<unsigned char>& out, const char* type, const unsigned char* data,
           std::size_t size) {
  put32(out, static_cast<std::uint32_t>(size));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  if (size > 0) out.insert(out.end(), data, data + size);
  put32(out, static_cast<std::uint32_t>(
                 crc32(0, out.data() + start, static_cast<uInt>(out.size() - start))));
}

}  // namespace

void write_png_fast(const Image& image, const std::string& path) {
  if (image.empty() ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw Error("write_png_fast: image for '" + path + "' is empty or inconsistent");
  }
  const std::size_t stride = static_cast<std::size_t>(image.width) * 4;
  // the filtered scanlines: a filter byte, then each byte minus its left neighbour's
  std::vector<unsigned char> raw((stride + 1) * image.height);
  for (int y = 0; y < image.height; ++y) {
    unsigned char* row = &raw[(stride + 1) * y];
    const std::uint8_t* src = image.pixel(0, y);
    row[0] = kFilterSub;
    for (std::size_t i = 0; i < stride; ++i)
      row[1 + i] = static_cast<unsigned char>(src[i] - (i >= 4 ? src[i - 4] : 0));
  }
  uLongf packed_size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<unsigned char> packed(packed_size);
  if (compress2(packed.data(), &packed_size, raw.data(), static_cast<uLong>(raw.size()),
                kDeflateLevel) != Z_OK) {
    throw Error("write_png_fast: zlib failed to compress '" + path + "'");
  }

  std::vector<unsigned char> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<unsigned char> header;
  put32(header, static_cast<std::uint32_t>(image.width));
  put32(header, static_cast<std::uint32_t>(image.height));
  header.insert(header.end(), {8, 6, 0, 0, 0});  // 8 bits, RGBA, deflate, adaptive, no interlace
  chunk(out, "IHDR", header.data(), header.size());
  chunk(out, "IDAT", packed.data(), packed_size);
  chunk(out, "IEND", nullptr, 0);

  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!f || std::fwrite(out.data(), 1, out.size(), f.get()) != out.size()) {
    throw Error("cannot write PNG '" + path + "' (does its folder exist and is it writable?)");
  }
}

}  // namespace pcsg::render
