#pragma once
// Compiled programs keyed by their files and defines, so a pass that runs every frame compiles
// its shaders once.
#include <map>
#include <string>
#include <string_view>

#include "renderer/gpu/shader_program.hpp"

namespace tlab::gpu {

class ShaderCache {
 public:
  const ShaderProgram& graphics(std::string_view vertexFile, std::string_view fragmentFile, const ShaderDefines& defines = {});
  const ShaderProgram& compute(std::string_view computeFile, const ShaderDefines& defines = {});
  // A program compiled from assembled source (a style file's), cached under `key`.
  const ShaderProgram& computeFromSource(const std::string& key, const std::string& source, std::string_view what);

 private:
  static std::string key(std::string_view a, std::string_view b, const ShaderDefines& defines);
  std::map<std::string, ShaderProgram> programs_;
};

}  // namespace tlab::gpu
