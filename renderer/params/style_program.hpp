#pragma once
// The GLSL of a style file, ready to compile into one of the renderer's stages: tlab's prelude
// (the fragment accessors), the parameters as uniforms, the user's file under `#line 1 1`, and
// the stage's main(). A compile error in the user's code becomes "FILE:LINE: message" with the
// line of the user's file (GLSL source-string 1); an error outside it names the file's first line.
#include <string>
#include <string_view>
#include <vector>

#include "renderer/gpu/shader_cache.hpp"

namespace tlab::render {

enum class StyleValueType { Float, Int, Bool };

struct StyleUniform {
  std::string name;
  StyleValueType type = StyleValueType::Float;
  double value = 0.0;
};

struct StyleProgram {
  std::string path;    // the style file, for messages
  std::string sha256;  // of text: the cache key
  std::string text;    // the user's file
  std::vector<StyleUniform> uniforms;

  // Compiles (once per shader cache) the program for `mainFile` (an embedded GLSL file holding the
  // prelude's #includes and main(), starting with #version) with `defines`; throws
  // std::invalid_argument "FILE:LINE: message" when the user's code does not compile.
  const gpu::ShaderProgram& compile(gpu::ShaderCache& shaders, std::string_view mainFile, const gpu::ShaderDefines& defines) const;
  // Sets the parameter uniforms on the bound program.
  void setUniforms(const gpu::ShaderProgram& program) const;
};

// The full source compile() hands to the driver (exposed for tests).
std::string assembleStyleSource(const StyleProgram& style, std::string_view mainFile, const gpu::ShaderDefines& defines);

// Maps a GLSL compiler log (Mesa "1:12(5): error: ..." or NVIDIA "1(12) : error C...: ...") to
// one line "FILE:LINE: message" for the first error; lines of other source strings name line 1.
std::string mapStyleCompileLog(const std::string& path, const std::string& log);

}  // namespace tlab::render
