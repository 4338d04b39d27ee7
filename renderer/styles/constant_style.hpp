#pragma once
#include "renderer/styles/style.hpp"

namespace tlab::render {

// `constant`: every layer with the same opacity α, blended front to back with float
// accumulation (Carnecky Fig. 11(b), Eq. 4).
class ConstantStyle final : public Style {
 public:
  std::string name() const override { return "constant"; }
  std::string description() const override { return "constant opacity alpha on every layer, front-to-back blending"; }
  std::vector<ParamSpec> params() const override;
  FillSpec fill(const StyleParams&) const override;  // the compose pass sorts (compose/blend.comp)
  FragmentProperties properties(const StyleParams& params, const SceneFacts& facts) const override;
  std::vector<std::unique_ptr<RenderPass>> passes(const StyleParams& params) const override;
};

}  // namespace tlab::render
