#include "renderer/styles/constant_style.hpp"

#include "renderer/compose/blend_compositor.hpp"

namespace tlab::render {

std::vector<ParamSpec> ConstantStyle::params() const {
  return {ParamSpec::number("alpha", 0.25, 0.0, 1.0, "opacity of every layer")};
}

FillSpec ConstantStyle::fill(const StyleParams&) const {
  FillSpec spec;
  spec.sortsInCompose = true;
  return spec;
}

FragmentProperties ConstantStyle::properties(const StyleParams&, const SceneFacts&) const {
  FragmentProperties p;
  p |= FragmentProperty::Color;
  return p;
}

std::vector<std::unique_ptr<RenderPass>> ConstantStyle::passes(const StyleParams& params) const {
  std::vector<std::unique_ptr<RenderPass>> p;
  p.push_back(functionPass("compose", [alpha = static_cast<float>(params.number("alpha"))](FrameContext& f) { composeBlend(f, alpha); }));
  return p;
}

}  // namespace tlab::render
