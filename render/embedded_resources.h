#pragma once
// Files compiled into the binary at build time (render/embed_resources.cmake): the GLSL sources
// of shaders/ and the label font, so that pcsg never reads its source tree at run time.
#include <cstddef>
#include <string_view>

namespace pcsg::render {

struct EmbeddedResource {
  const unsigned char* data = nullptr;  // followed by one zero byte (usable as a C string)
  std::size_t size = 0;                 // without that zero byte
  bool empty() const { return data == nullptr; }
  std::string_view text() const { return {reinterpret_cast<const char*>(data), size}; }
};

// The file with base name `name` ("surface.vert", "label_font.ttf"); empty when not embedded.
EmbeddedResource embedded_resource(std::string_view name);

// True when the label font (DejaVu Sans) was embedded at build time; otherwise labels use
// ImGui's built-in bitmap font and images differ from the golden ones.
inline bool has_label_font() { return !embedded_resource("label_font.ttf").empty(); }

}  // namespace pcsg::render
