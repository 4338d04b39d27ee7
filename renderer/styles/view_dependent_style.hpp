#pragma once
#include "renderer/styles/style.hpp"

namespace tlab::render {

// `view-dependent`: transparency in interactive technical illustrations (Diepstraten et al.
// 2002): α falls off from the object-space silhouettes (Eqs. 1-2), only the nearest transparent
// front face is blended with the opaque surface or background behind it (Sec. 4), with implicit
// (Sec. 6.1) or explicit (Sec. 6.2) interior boundaries, Gooch shading and black silhouette lines.
// Objects with Role::Opaque are opaque; every other object is transparent.
class ViewDependentStyle final : public Style {
 public:
  std::string name() const override { return "view-dependent"; }
  std::string description() const override {
    return "Diepstraten 2002: silhouette-distance alpha, nearest transparent layer over opaque objects, lines";
  }
  std::vector<ParamSpec> params() const override;
  FragmentProperties properties(const StyleParams& params, const SceneFacts& facts) const override;
  std::vector<std::unique_ptr<RenderPass>> passes(const StyleParams& params) const override;
};

}  // namespace tlab::render
