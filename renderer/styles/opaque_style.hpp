#pragma once
#include "renderer/styles/style.hpp"

namespace tlab::render {

// `opaque`: the nearest surface through the ordinary z-buffer (Carnecky Fig. 11(a)); builds no
// fragment lists.
class OpaqueStyle final : public Style {
 public:
  std::string name() const override { return "opaque"; }
  std::string description() const override { return "nearest surface only, z-buffered (no fragment lists)"; }
  std::vector<ParamSpec> params() const override { return {}; }
  FillSpec fill(const StyleParams&) const override { return {FillSpec::Kind::None}; }
  FragmentProperties properties(const StyleParams&, const SceneFacts&) const override { return {}; }
  std::vector<std::unique_ptr<RenderPass>> passes(const StyleParams& params) const override;
};

}  // namespace tlab::render
