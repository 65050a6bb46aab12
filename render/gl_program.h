#pragma once
// A linked GLSL program built from shaders embedded at build time (shaders/*.vert|geom|frag),
// with its uniform locations looked up once.
#include <string>
#include <unordered_map>
#include <vector>

#include "render/gl_handle.h"

namespace pcsg::render {

class GlProgram {
 public:
  GlProgram() = default;
  // Compiles and links the named shaders (file names in shaders/, the stage taken from the
  // extension). Throws pcsg::Error with the file name and the compiler's log when one fails.
  explicit GlProgram(const std::vector<std::string>& shader_files);

  void use() const { glUseProgram(program_.id()); }
  GLuint id() const { return program_.id(); }
  // Location of a uniform (-1 when the linker dropped it as unused; setting -1 is a no-op).
  GLint uniform(const std::string& name);

 private:
  std::string name_;  // the shader files, for messages
  GlHandle program_;
  std::unordered_map<std::string, GLint> uniforms_;
};

}  // namespace pcsg::render
