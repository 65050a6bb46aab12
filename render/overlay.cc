#include "render/overlay.h"

#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "engine/core/error.h"
#include "render/embedded_resources.h"
#include "render/gl_api.h"

namespace pcsg::render {

namespace {

// Font sizes in pixels at the reference image height; they scale with the image height.
constexpr float kReferenceHeight = 960.f;
constexpr float kLabelPx = 19.f;
constexpr float kTitlePx = 23.f;
constexpr float kSubtitlePx = 19.f;
// Below this scale text would be unreadable anyway; keep a floor for thumbnails.
constexpr float kMinScale = 0.5f;
// Fixed frame time: ImGui only uses it for animations, and a constant keeps frames identical.
constexpr float kFrameSeconds = 1.f / 60.f;

// Guards Dear ImGui's global current context (see Overlay::draw).
std::mutex& imgui_mutex() {
  static std::mutex m;
  return m;
}

float base_px(FontRole role) {
  switch (role) {
    case FontRole::Label:
      return kLabelPx;
    case FontRole::Title:
      return kTitlePx;
    case FontRole::Subtitle:
      return kSubtitlePx;
  }
  return kLabelPx;
}

}  // namespace

Overlay::Overlay() {
  const std::scoped_lock lock(imgui_mutex());
  IMGUI_CHECKVERSION();
  ImGuiContext* previous = ImGui::GetCurrentContext();
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // never write imgui.ini next to the user's files
  io.LogFilename = nullptr;
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
    ImGui::DestroyContext(context_);
    ImGui::SetCurrentContext(previous);
    throw Error("Dear ImGui's OpenGL3 backend failed to initialise");
  }
  build_fonts(1.f);
  ImGui_ImplOpenGL3_CreateDeviceObjects();  // shader and font texture
  ImGui::SetCurrentContext(previous);
}

Overlay::~Overlay() {
  const std::scoped_lock lock(imgui_mutex());
  ImGui::SetCurrentContext(context_);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext(context_);
}

void Overlay::build_fonts(float scale) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  const EmbeddedResource ttf = embedded_resource("label_font.ttf");
  for (FontRole role : {FontRole::Label, FontRole::Title, FontRole::Subtitle}) {
    const float px = std::round(base_px(role) * scale);
    ImFont* font = nullptr;
    if (!ttf.empty()) {
      ImFontConfig config;
      config.FontDataOwnedByAtlas = false;  // the data is the binary's, not the heap's
      // stb_truetype only reads the data; the API takes it non-const for historic reasons
      font = io.Fonts->AddFontFromMemoryTTF(const_cast<unsigned char*>(ttf.data),
                                            static_cast<int>(ttf.size), px, &config);
    } else {
      ImFontConfig config;
      config.SizePixels = px;
      font = io.Fonts->AddFontDefault(&config);
    }
    fonts_[static_cast<int>(role)] = font;
  }
  io.Fonts->Build();
  scale_ = scale;
}

void Overlay::draw(int width, int height, const std::function<void(Overlay&)>& paint) {
  const std::scoped_lock lock(imgui_mutex());
  ImGui::SetCurrentContext(context_);
  const float scale = std::max(kMinScale, static_cast<float>(height) / kReferenceHeight);
  if (scale != scale_) {
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    build_fonts(scale);
    ImGui_ImplOpenGL3_CreateFontsTexture();
  }
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  io.DisplayFramebufferScale = ImVec2(1.f, 1.f);
  io.DeltaTime = kFrameSeconds;
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
  paint(*this);
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  ImGui::SetCurrentContext(nullptr);
}

ImDrawList& Overlay::draw_list() { return *ImGui::GetBackgroundDrawList(); }

ImFont* Overlay::font(FontRole role) const { return fonts_[static_cast<int>(role)]; }

float Overlay::font_size(FontRole role) const { return font(role)->FontSize; }

ImVec2 Overlay::text_size(FontRole role, const std::string& text) const {
  ImFont* f = font(role);
  return f->CalcTextSizeA(f->FontSize, 1e9f, 0.f, text.c_str(), text.c_str() + text.size());
}

}  // namespace pcsg::render
