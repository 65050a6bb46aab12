#include "render/id_target.h"

#include <algorithm>
#include <string>

#include "engine/core/error.h"

namespace pcsg::render {

void IdTarget::allocate(int width, int height) {
  width_ = width;
  height_ = height;
  ids_ = GlHandle(GlKind::Renderbuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, ids_.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_R32I, width, height);
  depth_ = GlHandle(GlKind::Renderbuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  fbo_ = GlHandle(GlKind::Framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ids_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw Error("element-id framebuffer (" + std::to_string(width) + "x" + std::to_string(height) +
                ") is incomplete: GL status " + std::to_string(status));
  }
}

void IdTarget::begin() {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0};
  glDrawBuffers(1, buffers);
  glViewport(0, 0, width_, height_);
  const GLint background[] = {0, 0, 0, 0};
  glClearBufferiv(GL_COLOR, 0, background);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
}

IdImage IdTarget::read(double scale) {
  IdImage image;
  image.width = width_;
  image.height = height_;
  image.scale = scale;
  std::vector<std::int32_t> bottom_up(static_cast<std::size_t>(width_) * height_);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width_, height_, GL_RED_INTEGER, GL_INT, bottom_up.data());
  image.ids.resize(bottom_up.size());
  for (int y = 0; y < height_; ++y) {
    std::copy_n(bottom_up.begin() + static_cast<std::ptrdiff_t>(height_ - 1 - y) * width_, width_,
                image.ids.begin() + static_cast<std::ptrdiff_t>(y) * width_);
  }
  return image;
}

}  // namespace pcsg::render
