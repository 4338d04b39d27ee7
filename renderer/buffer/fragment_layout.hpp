#pragma once
// Which properties each fragment record carries, and where (Carnecky Sec. 4.1: fragData holds
// application-dependent properties). A style asks for what it uses and pays for nothing else.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/gpu/shader_program.hpp"

namespace tlab::render {

enum class FragmentProperty : std::uint32_t {
  Color = 1u << 0,          // shaded colour, RGBA8 (1 word)
  Normal = 1u << 1,         // view-space unit normal, octahedral 2 x 16 bits (1 word)
  DepthGradient = 1u << 2,  // (dz/dx, dz/dy) of eye-space depth (2 words)
  Ids = 1u << 3,            // object id | component id | front-facing flag (1 word)
  SurfaceParams = 1u << 4,  // (s, t) (2 words)
  // Screen-space derivatives of the shading attributes, taken by the rasterizer (dFdx/dFdy) as
  // depth peeling takes them, so both renderers of the IRIS styles share one definition:
  NormalZGradient = 1u << 5,  // (∂n_z/∂x, ∂n_z/∂y) of the unit view normal (2 words)
  StGradient = 1u << 6,       // (∂s/∂x, ∂s/∂y, ∂t/∂x, ∂t/∂y) (4 words)
};

struct FragmentProperties {
  std::uint32_t bits = 0;
  FragmentProperties& operator|=(FragmentProperty p) { bits |= std::uint32_t(p); return *this; }
  bool has(FragmentProperty p) const { return (bits & std::uint32_t(p)) != 0; }
};

// Word offsets of each property in one fragment record. Words 0 and 1 are always the eye-space
// depth and the global triangle index (the sort key and its tie-break).
struct FragmentLayout {
  explicit FragmentLayout(FragmentProperties properties);
  FragmentProperties properties;
  std::uint32_t stride = 2;  // words per fragment
  std::uint32_t words = 2;   // the words the properties take: stride without the padding
  std::uint32_t quads = 0;   // stride / 4 where the record is padded to whole uvec4s, else 0
  std::uint32_t colorOffset = 0, normalOffset = 0, depthGradientOffset = 0, idsOffset = 0, stOffset = 0;
  std::uint32_t nzGradientOffset = 0, stGradientOffset = 0;
  // TLAB_STRIDE, TLAB_HAS_*, TLAB_OFF_* for the shaders.
  gpu::ShaderDefines defines() const;
  std::vector<std::string> propertyNames() const;
};

// The host-side inverse of encodeNormal in frame/fragment_layout.glsl.
glm::vec3 decodeNormal(std::uint32_t word);

}  // namespace tlab::render
