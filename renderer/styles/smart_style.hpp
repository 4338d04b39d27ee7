#pragma once
#include "renderer/styles/style.hpp"

namespace tlab::render {

// `smart`: smart transparency of Carnecky et al. 2013 (Secs. 4.4-5.5): neighbour links, the α, β,
// γ fields, their diffusion and spreading, profile modifiers, and Alg. 3 compositing.
class SmartStyle final : public Style {
 public:
  std::string name() const override { return "smart"; }
  std::string description() const override {
    return "smart transparency (Carnecky 2013): silhouette highlights and halos diffused along the surface";
  }
  std::vector<ParamSpec> params() const override;
  void validate(const StyleParams& params) const override;
  FragmentProperties properties(const StyleParams& params, const SceneFacts& facts) const override;
  // The buffer with the colour plane: Alg. 3's compositing reads only the colour of the records.
  FillSpec fill(const StyleParams&) const override {
    FillSpec spec;
    spec.colorPlane = true;
    return spec;
  }
  std::vector<std::unique_ptr<RenderPass>> passes(const StyleParams& params) const override;
};

}  // namespace tlab::render
