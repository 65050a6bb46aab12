#pragma once
// An OpenGL (3.3+ core) context with an offscreen multisampled render target, behind one small
// interface so that the context's origin (OSMesa today; an EGL surfaceless display later, since
// Mesa 25.1 dropped OSMesa) stays out of the renderer. No GL header here: the app includes it.
#include <memory>
#include <string>

#include "render/image.h"

namespace pcsg::render {

enum class GlBackend {
  OSMesa,  // Mesa's software context (llvmpipe); needs no display, no GPU, no X
};

class GlContext {
 public:
  virtual ~GlContext() = default;
  GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Binds the context to the calling thread; GL calls of render/ need it current.
  virtual void make_current() = 0;
  virtual int width() const = 0;
  virtual int height() const = 0;
  // Samples per pixel of the target (4 when MSAA is on, 1 when off).
  virtual int samples() const = 0;
  // Reallocates the target at a new size (the context and its objects stay alive).
  virtual void resize(int width, int height) = 0;
  // GL name of the framebuffer to draw into: colour attachment 0 (RGBA8) and depth-stencil
  // belong to the context. A client may attach its own buffers of the same size and sample
  // count at GL_COLOR_ATTACHMENT1 and up (it sets glDrawBuffers itself).
  virtual unsigned framebuffer() const = 0;
  // Resolves the multisampled colour attachment 0 and reads it back, rows top first.
  virtual Image read_pixels() = 0;
  // "GL_RENDERER, GL_VERSION", for messages and logs.
  virtual std::string description() const = 0;
  // The context's GL version as major * 10 + minor (45 for 4.5), and whether it is a core
  // profile: what the renderer's shaders (#version 330 core) need.
  virtual int gl_version() const = 0;
  virtual bool core_profile() const = 0;
};

// Creates a context of the backend with a width x height target of `samples` samples per pixel
// (clamped to what the implementation supports; 1 for no MSAA), current on the calling thread.
// Throws pcsg::Error naming the backend and the failed step when it cannot.
std::unique_ptr<GlContext> create_gl_context(int width, int height, int samples,
                                             GlBackend backend = GlBackend::OSMesa);

}  // namespace pcsg::render
