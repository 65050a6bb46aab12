#include "render/msaa_target.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>

#include "engine/core/error.h"

namespace pcsg::render {

namespace {

void check_complete(GLenum target, const char* what, int w, int h, int samples) {
  const GLenum status = glCheckFramebufferStatus(target);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", status);
    throw Error(std::string("offscreen framebuffer (") + what + ", " + std::to_string(w) + "x" +
                std::to_string(h) + ", " + std::to_string(samples) +
                " samples) is incomplete: status " + code);
  }
}

}  // namespace

void MsaaTarget::allocate(int width, int height, int samples) {
  GLint max_size = 0, max_samples = 1;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (width < 1 || height < 1 || width > max_size || height > max_size) {
    throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                " is outside 1.." + std::to_string(max_size) + " pixels per side");
  }
  width_ = width;
  height_ = height;
  samples_ = std::clamp(samples, 1, std::max(1, max_samples));
  // 0 asks for an ordinary (single-sample) renderbuffer.
  const GLsizei storage_samples = samples_ > 1 ? samples_ : 0;

  msaa_color_ = GlHandle(GlKind::Renderbuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, msaa_color_.id());
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, storage_samples, GL_RGBA8, width, height);
  msaa_depth_ = GlHandle(GlKind::Renderbuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, msaa_depth_.id());
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, storage_samples, GL_DEPTH24_STENCIL8, width,
                                   height);
  msaa_fbo_ = GlHandle(GlKind::Framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            msaa_color_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                            msaa_depth_.id());
  check_complete(GL_FRAMEBUFFER, "multisampled", width, height, samples_);

  resolve_color_ = GlHandle(GlKind::Renderbuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, resolve_color_.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  resolve_fbo_ = GlHandle(GlKind::Framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            resolve_color_.id());
  check_complete(GL_FRAMEBUFFER, "resolve", width, height, 1);

  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_.id());
}

Image MsaaTarget::read_pixels() {
  // resolve: averaging the samples of attachment 0 (a blit between different sample counts)
  glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo_.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_.id());
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);

  // read back, then flip: GL's row 0 is the bottom one, PNG's the top one
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  Image bottom_up(width_, height_);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.rgba.data());
  Image image(width_, height_);
  const std::size_t row = static_cast<std::size_t>(width_) * 4;
  for (int y = 0; y < height_; ++y) {
    std::memcpy(image.rgba.data() + row * y, bottom_up.rgba.data() + row * (height_ - 1 - y), row);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_.id());
  return image;
}

void MsaaTarget::release() {
  msaa_fbo_.reset();
  msaa_color_.reset();
  msaa_depth_.reset();
  resolve_fbo_.reset();
  resolve_color_.reset();
}

}  // namespace pcsg::render
