#pragma once
// Move-only owners of GL object names, so that every buffer, texture and framebuffer is
// released exactly once. Deleting needs the owning context current: owners of GL objects
// make their context current before they are destroyed.
#include <utility>

#include "render/gl_api.h"

namespace pcsg::render {

enum class GlKind { Buffer, VertexArray, Texture, Renderbuffer, Framebuffer, Program };

class GlHandle {
 public:
  GlHandle() = default;
  explicit GlHandle(GlKind kind) : kind_(kind) {
    switch (kind_) {
      case GlKind::Buffer:
        glGenBuffers(1, &id_);
        break;
      case GlKind::VertexArray:
        glGenVertexArrays(1, &id_);
        break;
      case GlKind::Texture:
        glGenTextures(1, &id_);
        break;
      case GlKind::Renderbuffer:
        glGenRenderbuffers(1, &id_);
        break;
      case GlKind::Framebuffer:
        glGenFramebuffers(1, &id_);
        break;
      case GlKind::Program:
        id_ = glCreateProgram();
        break;
    }
  }
  ~GlHandle() { reset(); }
  GlHandle(GlHandle&& o) noexcept : kind_(o.kind_), id_(std::exchange(o.id_, 0)) {}
  GlHandle& operator=(GlHandle&& o) noexcept {
    if (this != &o) {
      reset();
      kind_ = o.kind_;
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }

  void reset() {
    if (id_ == 0) return;
    switch (kind_) {
      case GlKind::Buffer:
        glDeleteBuffers(1, &id_);
        break;
      case GlKind::VertexArray:
        glDeleteVertexArrays(1, &id_);
        break;
      case GlKind::Texture:
        glDeleteTextures(1, &id_);
        break;
      case GlKind::Renderbuffer:
        glDeleteRenderbuffers(1, &id_);
        break;
      case GlKind::Framebuffer:
        glDeleteFramebuffers(1, &id_);
        break;
      case GlKind::Program:
        glDeleteProgram(id_);
        break;
    }
    id_ = 0;
  }

 private:
  GlKind kind_ = GlKind::Buffer;
  GLuint id_ = 0;
};

}  // namespace pcsg::render
