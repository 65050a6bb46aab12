// The OSMesa backend of GlContext: Mesa's software rasterizer (llvmpipe) with a 3.3+ core
// profile, no display and no GPU. OSMesa renders into a client buffer; we only give it a tiny
// one, because every frame goes to the context's own multisampled framebuffer (MsaaTarget).
// gl_api.h first: it defines GL_GLEXT_PROTOTYPES before <GL/gl.h> is included by osmesa.h.
#include "render/gl_api.h"
// (this comment line keeps clang-format from sorting the two includes)
#include <GL/osmesa.h>

#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "render/gl_context.h"
#include "render/msaa_target.h"

namespace pcsg::render {

namespace {

// OSMesa's own buffer is never drawn into (all drawing goes to FBOs); 1x1 keeps it free.
constexpr int kOSMesaBufferSide = 1;

class OSMesaGlContext final : public GlContext {
 public:
  OSMesaGlContext(int width, int height, int samples) {
    // core profile 3.3: shaders, FBOs, MSAA renderbuffers, geometry shaders, integer targets
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           0,
                           OSMESA_STENCIL_BITS,
                           0,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (context_ == nullptr) {
      throw Error(
          "OSMesa: cannot create an OpenGL 3.3 core profile context (OSMesaCreateContextAttribs "
          "failed; is Mesa's libOSMesa with llvmpipe installed?)");
    }
    buffer_.assign(kOSMesaBufferSide * kOSMesaBufferSide, 0);
    make_current();
    target_.allocate(width, height, samples);
  }

  ~OSMesaGlContext() override {
    make_current();
    target_.release();
    OSMesaDestroyContext(context_);
  }

  void make_current() override {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kOSMesaBufferSide,
                           kOSMesaBufferSide)) {
      throw Error("OSMesa: OSMesaMakeCurrent failed");
    }
  }
  int width() const override { return target_.width(); }
  int height() const override { return target_.height(); }
  int samples() const override { return target_.samples(); }
  void resize(int width, int height) override {
    if (width == target_.width() && height == target_.height()) return;
    target_.allocate(width, height, target_.samples());
  }
  unsigned framebuffer() const override { return target_.framebuffer(); }
  Image read_pixels() override { return target_.read_pixels(); }
  std::string description() const override {
    auto str = [](GLenum name) {
      const auto* s = reinterpret_cast<const char*>(glGetString(name));
      return std::string(s != nullptr ? s : "?");
    };
    return "OSMesa: " + str(GL_RENDERER) + ", " + str(GL_VERSION);
  }
  int gl_version() const override {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    return major * 10 + minor;
  }
  bool core_profile() const override {
    GLint mask = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
    return (mask & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
  }

 private:
  OSMesaContext context_ = nullptr;
  std::vector<std::uint32_t> buffer_;  // RGBA8 pixels of OSMesa's (unused) default buffer
  MsaaTarget target_;
};

}  // namespace

std::unique_ptr<GlContext> create_gl_context(int width, int height, int samples,
                                             GlBackend backend) {
  switch (backend) {
    case GlBackend::OSMesa:
      return std::make_unique<OSMesaGlContext>(width, height, samples);
  }
  throw Error("unknown GL backend " + std::to_string(static_cast<int>(backend)));
}

}  // namespace pcsg::render
