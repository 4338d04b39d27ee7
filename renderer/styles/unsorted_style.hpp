#pragma once
#include "renderer/styles/style.hpp"

namespace tlab::render {

// `unsorted`: plain GL alpha blending in submission order, no fragment lists. Wrong wherever
// layers overlap out of order — it is the speed floor that benchmarks compare against.
class UnsortedStyle final : public Style {
 public:
  std::string name() const override { return "unsorted"; }
  std::string description() const override { return "plain alpha blending in submission order (no sorting; the speed floor)"; }
  std::vector<ParamSpec> params() const override;
  FillSpec fill(const StyleParams&) const override { return {FillSpec::Kind::None}; }
  FragmentProperties properties(const StyleParams&, const SceneFacts&) const override { return {}; }
  std::vector<std::unique_ptr<RenderPass>> passes(const StyleParams& params) const override;
};

}  // namespace tlab::render
