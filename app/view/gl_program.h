#pragma once
// A linked GLSL program (needs a current OpenGL 3.3 core context).

#include <epoxy/gl.h>
#include <string>

namespace mtcut::app::view {

class GlProgram {
 public:
  // Compiles and links; throws std::runtime_error with the driver's log.
  GlProgram(const std::string& vertex_source, const std::string& fragment_source);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  GLuint id() const { return id_; }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

}  // namespace mtcut::app::view
