#include "render/gl_program.h"

#include <algorithm>

#include "engine/core/error.h"
#include "render/embedded_resources.h"

namespace pcsg::render {

namespace {

GLenum stage_of(const std::string& file) {
  auto ends_with = [&](const char* ext) {
    const std::string e(ext);
    return file.size() >= e.size() && file.compare(file.size() - e.size(), e.size(), e) == 0;
  };
  if (ends_with(".vert")) return GL_VERTEX_SHADER;
  if (ends_with(".geom")) return GL_GEOMETRY_SHADER;
  if (ends_with(".frag")) return GL_FRAGMENT_SHADER;
  throw Error("shader '" + file + "': unknown stage (expected .vert, .geom or .frag)");
}

std::string info_log(GLuint object, bool is_program) {
  GLint length = 0;
  if (is_program) {
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  } else {
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  }
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  if (is_program) {
    glGetProgramInfoLog(object, length, nullptr, log.data());
  } else {
    glGetShaderInfoLog(object, length, nullptr, log.data());
  }
  return log.c_str();
}

}  // namespace

GlProgram::GlProgram(const std::vector<std::string>& shader_files) : program_(GlKind::Program) {
  std::vector<GLuint> shaders;
  for (const auto& file : shader_files) {
    name_ += (name_.empty() ? "" : " + ") + file;
    const EmbeddedResource source = embedded_resource(file);
    if (source.empty()) {
      throw Error("shader '" + file + "' was not embedded at build time (is it in shaders/?)");
    }
    const GLuint shader = glCreateShader(stage_of(file));
    const auto* text = reinterpret_cast<const GLchar*>(source.data);
    const auto length = static_cast<GLint>(source.size);
    glShaderSource(shader, 1, &text, &length);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
      const std::string log = info_log(shader, false);
      glDeleteShader(shader);
      for (GLuint s : shaders) glDeleteShader(s);
      throw Error("shader '" + file + "' does not compile:\n" + log);
    }
    glAttachShader(program_.id(), shader);
    shaders.push_back(shader);
  }
  glLinkProgram(program_.id());
  // shaders are no longer needed once linked (deleting marks them; the program keeps its code)
  for (GLuint s : shaders) {
    glDetachShader(program_.id(), s);
    glDeleteShader(s);
  }
  GLint ok = GL_FALSE;
  glGetProgramiv(program_.id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    throw Error("shader program " + name_ + " does not link:\n" + info_log(program_.id(), true));
  }
}

GLint GlProgram::uniform(const std::string& name) {
  auto it = uniforms_.find(name);
  if (it == uniforms_.end()) {
    it = uniforms_.emplace(name, glGetUniformLocation(program_.id(), name.c_str())).first;
  }
  return it->second;
}

}  // namespace pcsg::render
