#pragma once
#include "renderer/styles/style.hpp"

namespace tlab::render {

// `curvature`: shape depiction for transparent objects with the bucketed k-buffer (seed 002,
// Murray et al.): the k nearest fragments per pixel grouped into per-shape buckets, neighbours
// found inside the same-shape bucket of each adjacent pixel with a reverse check, screen-space
// curvature κ = tanh(κ1 + κ2), then mean-curvature shading (1-D transfer function) and
// mean-curvature transparency (2-D transfer function of |κ| and depth).
class CurvatureStyle final : public Style {
 public:
  std::string name() const override { return "curvature"; }
  std::string description() const override {
    return "mean-curvature shading and transparency on the bucketed k-buffer (Murray et al. 2016)";
  }
  std::vector<ParamSpec> params() const override;
  FragmentProperties properties(const StyleParams& params, const SceneFacts& facts) const override;
  FillSpec fill(const StyleParams& params) const override;
  void validate(const StyleParams& params) const override;
  std::vector<std::unique_ptr<RenderPass>> passes(const StyleParams& params) const override;
};

}  // namespace tlab::render
