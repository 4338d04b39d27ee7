#pragma once
#include "renderer/styles/local_style.hpp"

namespace tlab::render {

// The IRIS styles (Hummel et al. 2010): `angle` (Sec. 3.1), `normal-variation` (Eq. 2) and `iris`
// (opacity chosen by a parameter, constant by default), each with window transparency, two-sided
// colouring, Phong/Gooch shading, adaptive stripes (Eqs. 3-5) and Sobel silhouettes (Sec. 5.1).
class IrisStyle final : public LocalStyle {
 public:
  // `selectable`: the opacity mode is the parameter `opacity` (style `iris`), else fixed.
  IrisStyle(std::string name, IllustrativeSettings::Opacity opacity, bool selectable);
  std::string name() const override { return name_; }
  std::string description() const override;
  std::vector<ParamSpec> params() const override;
  void validate(const StyleParams& params) const override;
  FragmentProperties properties(const StyleParams& params, const SceneFacts& facts) const override;
  std::vector<std::unique_ptr<RenderPass>> passes(const StyleParams& params) const override;
  IllustrativeSettings illustrative(const StyleParams& params) const override;

 private:
  IllustrativeSettings::Opacity opacityOf(const StyleParams& params) const;
  std::string name_;
  IllustrativeSettings::Opacity opacity_;
  bool selectable_;
};

}  // namespace tlab::render
