#include "renderer/styles/iris_style.hpp"

#include "renderer/compose/illustrative_compositor.hpp"

namespace tlab::render {

namespace {

using Opacity = IllustrativeSettings::Opacity;

}  // namespace

IrisStyle::IrisStyle(std::string name, Opacity opacity, bool selectable)
    : name_(std::move(name)), opacity_(opacity), selectable_(selectable) {}

std::string IrisStyle::description() const {
  if (selectable_) return "IRIS illustrative surfaces: opacity mode, window, stripes, silhouettes, Phong/Gooch";
  if (opacity_ == Opacity::Angle) return "IRIS angle-based opacity (2/pi)·arccos|n·v| in [alpha_min, alpha_max]";
  return "IRIS normal-variation opacity |grad n_z|^gamma in [alpha_min, alpha_max]";
}

std::vector<ParamSpec> IrisStyle::params() const {
  std::vector<ParamSpec> p;
  if (selectable_) {
    p.push_back(ParamSpec::choice("opacity", "constant", {"constant", "angle", "normal-variation"},
                                  "constant α, angle-based (Sec. 3.1) or normal variation (Eq. 2)"));
    p.push_back(ParamSpec::number("alpha", 0.25, 0, 1, "opacity when opacity=constant"));
  }
  p.push_back(ParamSpec::number("alpha_min", 0.1, 0, 1, "α where the view-dependent term is 0 (IRIS Sec. 3.2)"));
  p.push_back(ParamSpec::number("alpha_max", 0.9, 0, 1, "α where the view-dependent term is 1"));
  if (selectable_ || opacity_ == Opacity::NormalVariation)
    p.push_back(ParamSpec::number("gamma", 0.5, 0, 1, "exponent γ of Eq. 2 (applied after clamping)"));
  for (auto& spec : IllustrativeSettings::params()) p.push_back(std::move(spec));
  if (selectable_) {
    // `iris` alone shows the IRIS look (Figs. 1, 10): normal-variation opacity, two-sided colour,
    // adaptive s-stripes (pathlines) and silhouettes.
    for (auto& spec : p) {
      if (spec.name == "opacity") spec.defaultValue = "normal-variation";
      if (spec.name == "stripes") spec.defaultValue = "s";
      if (spec.name == "silhouettes") spec.defaultValue = "on";
    }
  }
  return p;
}

Opacity IrisStyle::opacityOf(const StyleParams& params) const {
  if (!selectable_) return opacity_;
  if (params.is("opacity", "angle")) return Opacity::Angle;
  if (params.is("opacity", "normal-variation")) return Opacity::NormalVariation;
  return Opacity::Constant;
}

IllustrativeSettings IrisStyle::illustrative(const StyleParams& params) const {
  return IllustrativeSettings::from(params, opacityOf(params));
}

void IrisStyle::validate(const StyleParams& params) const { illustrative(params); }

FragmentProperties IrisStyle::properties(const StyleParams& params, const SceneFacts&) const {
  const IllustrativeSettings s = illustrative(params);
  FragmentProperties p;
  p |= FragmentProperty::Normal;
  p |= FragmentProperty::Ids;  // object, and facing for two-sided colouring
  if (s.opacity == Opacity::NormalVariation) p |= FragmentProperty::NormalZGradient;  // IRIS Eq. 2
  if (s.stripes != 0) {
    p |= FragmentProperty::SurfaceParams;
    p |= FragmentProperty::StGradient;  // IRIS Eqs. 3-4
  }
  return p;
}

std::vector<std::unique_ptr<RenderPass>> IrisStyle::passes(const StyleParams& params) const {
  std::vector<std::unique_ptr<RenderPass>> p;
  p.push_back(functionPass("compose", [settings = illustrative(params)](FrameContext& f) { composeIllustrative(f, settings); }));
  return p;
}

}  // namespace tlab::render
