#include "renderer/gpu/shader_cache.hpp"

namespace tlab::gpu {

std::string ShaderCache::key(std::string_view a, std::string_view b, const ShaderDefines& defines) {
  std::string k = std::string(a) + "|" + std::string(b);
  for (const auto& [n, v] : defines) k += "|" + n + "=" + v;
  return k;
}

const ShaderProgram& ShaderCache::graphics(std::string_view vs, std::string_view fs, const ShaderDefines& defines) {
  const std::string k = key(vs, fs, defines);
  auto it = programs_.find(k);
  if (it == programs_.end()) it = programs_.emplace(k, ShaderProgram::graphics(vs, fs, defines)).first;
  return it->second;
}

const ShaderProgram& ShaderCache::compute(std::string_view cs, const ShaderDefines& defines) {
  const std::string k = key(cs, "", defines);
  auto it = programs_.find(k);
  if (it == programs_.end()) it = programs_.emplace(k, ShaderProgram::compute(cs, defines)).first;
  return it->second;
}

const ShaderProgram& ShaderCache::computeFromSource(const std::string& key, const std::string& source, std::string_view what) {
  const std::string k = "source|" + key;
  auto it = programs_.find(k);
  if (it == programs_.end()) it = programs_.emplace(k, ShaderProgram::computeFromSource(source, what)).first;
  return it->second;
}

}  // namespace tlab::gpu
