#include "renderer/buffer/fragment_layout.hpp"

#include <algorithm>
#include <cmath>

namespace tlab::render {

FragmentLayout::FragmentLayout(FragmentProperties p) : properties(p) {
  const auto take = [&](FragmentProperty prop, std::uint32_t words, std::uint32_t& offset) {
    if (!p.has(prop)) return;
    offset = stride;
    stride += words;
  };
  take(FragmentProperty::Color, 1, colorOffset);
  take(FragmentProperty::Normal, 1, normalOffset);
  take(FragmentProperty::DepthGradient, 2, depthGradientOffset);
  take(FragmentProperty::Ids, 1, idsOffset);
  take(FragmentProperty::SurfaceParams, 2, stOffset);
  take(FragmentProperty::NormalZGradient, 2, nzGradientOffset);
  take(FragmentProperty::StGradient, 4, stGradientOffset);
  // Records of 4 words or more are padded to whole quads of words (TLAB_RECORD_QUADS): the
  // passes then move them as uvec4s, which llvmpipe loads and stores at about half the cost
  // of four single words (issue #29).
  words = stride;
  if (stride >= 4) {
    stride = (stride + 3) / 4 * 4;
    quads = stride / 4;
  }
}

gpu::ShaderDefines FragmentLayout::defines() const {
  gpu::ShaderDefines d = {{"TLAB_STRIDE", std::to_string(stride) + "u"}};
  if (quads > 0) d.emplace_back("TLAB_RECORD_QUADS", std::to_string(quads) + "u");
  const auto add = [&](FragmentProperty prop, const char* name, std::uint32_t offset) {
    if (!properties.has(prop)) return;
    d.emplace_back(std::string("TLAB_HAS_") + name, "1");
    d.emplace_back(std::string("TLAB_OFF_") + name, std::to_string(offset) + "u");
  };
  add(FragmentProperty::Color, "COLOR", colorOffset);
  add(FragmentProperty::Normal, "NORMAL", normalOffset);
  add(FragmentProperty::DepthGradient, "DEPTH_GRADIENT", depthGradientOffset);
  add(FragmentProperty::Ids, "IDS", idsOffset);
  add(FragmentProperty::SurfaceParams, "ST", stOffset);
  add(FragmentProperty::NormalZGradient, "NZ_GRADIENT", nzGradientOffset);
  add(FragmentProperty::StGradient, "ST_GRADIENT", stGradientOffset);
  return d;
}

std::vector<std::string> FragmentLayout::propertyNames() const {
  std::vector<std::string> names = {"depth", "triangle"};
  if (properties.has(FragmentProperty::Color)) names.push_back("color");
  if (properties.has(FragmentProperty::Normal)) names.push_back("normal");
  if (properties.has(FragmentProperty::DepthGradient)) names.push_back("depth_gradient");
  if (properties.has(FragmentProperty::Ids)) names.push_back("ids");
  if (properties.has(FragmentProperty::SurfaceParams)) names.push_back("st");
  if (properties.has(FragmentProperty::NormalZGradient)) names.push_back("nz_gradient");
  if (properties.has(FragmentProperty::StGradient)) names.push_back("st_gradient");
  return names;
}

glm::vec3 decodeNormal(std::uint32_t word) {
  // unpackSnorm2x16: clamp(int16 / 32767, -1, 1), low half first.
  const auto component = [](std::uint16_t bits) {
    return std::clamp(float(static_cast<std::int16_t>(bits)) / 32767.0f, -1.0f, 1.0f);
  };
  const glm::vec2 e(component(std::uint16_t(word & 0xFFFF)), component(std::uint16_t(word >> 16)));
  glm::vec3 n(e, 1.0f - std::abs(e.x) - std::abs(e.y));
  if (n.z < 0.0f) {
    const glm::vec2 w = (1.0f - glm::abs(glm::vec2(n.y, n.x))) *
                        glm::vec2(n.x >= 0.0f ? 1.0f : -1.0f, n.y >= 0.0f ? 1.0f : -1.0f);
    n.x = w.x;
    n.y = w.y;
  }
  return glm::normalize(n);
}

}  // namespace tlab::render
