#pragma once
// The offscreen target every GlContext backend draws into: a multisampled framebuffer (RGBA8
// colour + 24-bit depth, 8-bit stencil) and a single-sample one that it is resolved into
// before the pixels are read back. Independent of where the context came from.
#include "render/gl_handle.h"
#include "render/image.h"

namespace pcsg::render {

class MsaaTarget {
 public:
  // (Re)allocates both framebuffers; samples is clamped to GL_MAX_SAMPLES (1: no MSAA).
  // Throws pcsg::Error when the framebuffer is incomplete.
  void allocate(int width, int height, int samples);
  GLuint framebuffer() const { return msaa_fbo_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  // Blits colour attachment 0 into the resolve framebuffer and reads it, rows top first.
  Image read_pixels();
  void release();

 private:
  int width_ = 0, height_ = 0, samples_ = 1;
  GlHandle msaa_fbo_, msaa_color_, msaa_depth_;
  GlHandle resolve_fbo_, resolve_color_;
};

}  // namespace pcsg::render
