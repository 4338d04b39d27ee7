#pragma once
// Compiles GLSL programs from the shader files embedded at build time. Sources may say
// `#include "name.glsl"` (resolved against the embedded files). Compile and link failures become
// GlError exceptions naming the shader file and carrying the driver's log.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/gl_objects.hpp"

namespace tlab::gpu {

std::string_view embeddedShader(std::string_view name);  // generated at build time

// A shader that failed to compile: the message of GlError, and the driver's log as it wrote it
// (one line per diagnostic), so a caller that assembled the source can map lines back.
class ShaderCompileError : public GlError {
 public:
  ShaderCompileError(const std::string& message, std::string log) : GlError(message), log_(std::move(log)) {}
  const std::string& log() const { return log_; }

 private:
  std::string log_;
};

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;
// `a` followed by the defines of `b`.
ShaderDefines joined(ShaderDefines a, const ShaderDefines& b);

class ShaderProgram {
 public:
  ShaderProgram() = default;
  // A graphics program from a vertex and a fragment shader file.
  static ShaderProgram graphics(std::string_view vertexFile, std::string_view fragmentFile,
                                const ShaderDefines& defines = {});
  // A compute program from one file.
  static ShaderProgram compute(std::string_view computeFile, const ShaderDefines& defines = {});
  // A compute program from source text assembled by the caller (a style file's program);
  // `what` names it in errors.
  static ShaderProgram computeFromSource(const std::string& source, std::string_view what);

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
