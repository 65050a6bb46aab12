#pragma once
// Dear ImGui, used only as a 2D vector and text painter over the rendered image: one ImGui
// context per renderer, the OpenGL3 backend built from source (render/CMakeLists.txt), and
// the label font embedded at build time. No ImGui windows are used, only the background draw
// list, so the "auto-sized windows are hidden on their first frame" trap does not arise and a
// single frame per image suffices.
#include <imgui.h>

#include <functional>
#include <string>

namespace pcsg::render {

enum class FontRole { Label, Title, Subtitle };

class Overlay {
 public:
  // The GL context must be current (the backend compiles its shader and uploads the font).
  Overlay();
  ~Overlay();  // the GL context must be current
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;

  // Draws one frame of 2D decorations over the currently bound framebuffer: `paint` fills
  // draw_list() for a width x height image. Font sizes follow the image height (see
  // kReferenceHeight in overlay.cc), so a 640x480 image looks like a scaled 1280x960 one.
  // Dear ImGui keeps its current context in a global, so frames of all overlays are
  // serialised by one mutex: renderers in different threads stay correct.
  void draw(int width, int height, const std::function<void(Overlay&)>& paint);

  // For `paint`:
  ImDrawList& draw_list();
  ImFont* font(FontRole role) const;
  float font_size(FontRole role) const;
  // Size of `text` in pixels in the given font.
  ImVec2 text_size(FontRole role, const std::string& text) const;
  // Length scale of the frame's 2D decorations (1 at the reference height).
  float ui_scale() const { return scale_; }

 private:
  void build_fonts(float scale);

  ImGuiContext* context_ = nullptr;
  float scale_ = 0;  // the scale the font atlas was built for
  ImFont* fonts_[3] = {nullptr, nullptr, nullptr};
};

}  // namespace pcsg::render
