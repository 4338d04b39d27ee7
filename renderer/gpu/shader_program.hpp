#pragma once
// Compiles GLSL programs from the shader files embedded at build time. Sources may say
// `#include "name.glsl"` (resolved against the embedded files). Compile and link failures become
// GlError exceptions naming the shader file and carrying the driver's log.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "renderer/gpu/gl_objects.hpp"

namespace tlab::gpu {

std::string_view embeddedShader(std::string_view name);  // generated at build time

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;

class ShaderProgram {
 public:
  ShaderProgram() = default;
  // A graphics program from a vertex and a fragment shader file.
  static ShaderProgram graphics(std::string_view vertexFile, std::string_view fragmentFile,
                                const ShaderDefines& defines = {});
  // A compute program from one file.
  static ShaderProgram compute(std::string_view computeFile, const ShaderDefines& defines = {});

  GLuint id() const { return program_.id(); }
  void use() const { glUseProgram(program_.id()); }
  GLint uniform(const char* name) const { return glGetUniformLocation(program_.id(), name); }

 private:
  ProgramName program_;
};

// The full source text of a shader file after #include expansion and with `defines` inserted
// after the #version line. Exposed for tests and for error messages.
std::string preprocessShader(std::string_view file, const ShaderDefines& defines);

}  // namespace tlab::gpu
