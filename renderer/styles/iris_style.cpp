#include "renderer/styles/iris_style.hpp"

#include "renderer/compose/illustrative_compositor.hpp"
#include "renderer/ops/connect_pass.hpp"

namespace tlab::render {

namespace {

using Opacity = IllustrativeSettings::Opacity;

// What the passes of one frame share: the settings and the neighbour links.
struct IrisFrame {
  IllustrativeSettings settings;
  std::unique_ptr<TransparencyFields> fields;
};

// Geodesic neighbour links (Carnecky Alg. 2) for the screen-space derivatives of IRIS Eqs. 2-4.
class LinkPass final : public RenderPass {
 public:
  explicit LinkPass(std::shared_ptr<IrisFrame> f) : frame_(std::move(f)) {}
  std::string name() const override { return "connect"; }
  void run(FrameContext& frame) override {
    SmartSettings links;
    links.silhouettes = false;
    links.halos = false;
    frame_->fields = connectFragments(*frame.buffer, frame.shaders, links, frame.scene.boundingSphere().radius);
  }

 private:
  std::shared_ptr<IrisFrame> frame_;
};

class IllustrativeComposePass final : public RenderPass {
 public:
  explicit IllustrativeComposePass(std::shared_ptr<IrisFrame> f) : frame_(std::move(f)) {}
  std::string name() const override { return "compose"; }
  void run(FrameContext& frame) override {
    composeIllustrative(frame, frame_->settings, frame_->fields ? &frame_->fields->links() : nullptr);
  }

 private:
  std::shared_ptr<IrisFrame> frame_;
};

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
  if (s.needsScreenDerivatives()) p |= FragmentProperty::DepthGradient;  // for the neighbour links
  if (s.stripes != 0) p |= FragmentProperty::SurfaceParams;
  return p;
}

std::vector<std::unique_ptr<RenderPass>> IrisStyle::passes(const StyleParams& params) const {
  auto frame = std::make_shared<IrisFrame>();
  frame->settings = illustrative(params);
  std::vector<std::unique_ptr<RenderPass>> p;
  if (frame->settings.needsScreenDerivatives()) p.push_back(std::make_unique<LinkPass>(frame));
  p.push_back(std::make_unique<IllustrativeComposePass>(frame));
  return p;
}

}  // namespace tlab::render
