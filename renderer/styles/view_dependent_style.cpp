#include "renderer/styles/view_dependent_style.hpp"

#include "renderer/compose/view_dependent_compositor.hpp"

namespace tlab::render {

namespace {

struct ViewDependentFrame {
  ViewDependentSettings settings;
  ViewDependentAlpha* alpha = nullptr;  // the renderer's: its scene's edges, kept across frames
};

ViewDependentSettings settingsFrom(const StyleParams& p) {
  ViewDependentSettings s;
  s.explicitBoundaries = p.is("boundaries", "explicit");
  s.k = static_cast<float>(p.number("k"));
  s.alphaOpaque = static_cast<float>(p.number("alpha_opaque"));
  s.alphaBackground = static_cast<float>(p.number("alpha_background"));
  s.lines = p.is("lines", "on");
  s.additiveBlend = p.is("blend", "additive");
  s.shading.shading = p.is("shading", "gooch") ? IllustrativeSettings::Shading::Gooch : IllustrativeSettings::lightingShading(p);
  return s;
}

}  // namespace

std::vector<ParamSpec> ViewDependentStyle::params() const {
  return {
      ParamSpec::choice("boundaries", "explicit", {"explicit", "implicit"},
                        "interior boundaries modelled explicitly (Sec. 6.2) or given by the opaque objects (Sec. 6.1)"),
      ParamSpec::number("k", 0.5, 1e-3, 10, "fall-off exponent k of Eq. 2"),
      ParamSpec::number("alpha_opaque", 0.6, 0, 1, "weight of an opaque object seen through a transparent one"),
      ParamSpec::number("alpha_background", 0.5, 0, 1, "weight of the background seen through a transparent object"),
      ParamSpec::choice("lines", "on", {"on", "off"}, "black silhouette lines"),
      ParamSpec::choice("blend", "normalized", {"normalized", "additive"},
                        "c = a c_T + w c_dst (Sec. 7, GL_SRC_ALPHA/GL_DST_ALPHA, w = alpha_opaque or "
                        "alpha_background), divided by a + w where that exceeds 1 (no wash-out), or the literal sum"),
      ParamSpec::choice("shading", "gooch", {"gooch", "lighting"}, "Gooch cool/warm tones (Sec. 7) or the common lighting"),
  };
}

FragmentProperties ViewDependentStyle::properties(const StyleParams&, const SceneFacts&) const {
  FragmentProperties p;
  p |= FragmentProperty::Normal;
  p |= FragmentProperty::Ids;
  return p;
}

std::vector<std::unique_ptr<RenderPass>> ViewDependentStyle::passes(const StyleParams& params) const {
  auto frame = std::make_shared<ViewDependentFrame>();
  frame->settings = settingsFrom(params);
  std::vector<std::unique_ptr<RenderPass>> p;
  // Silhouette edges (Eq. 1) and per-vertex α (Eq. 2) for this frame's eye. The edge adjacency
  // and the uploaded mesh depend on the scene alone: built on the renderer's first frame of this
  // style, only the silhouettes and α are redone per frame.
  p.push_back(functionPass("silhouettes", [frame](FrameContext& f) {
    frame->alpha = &f.derived<ViewDependentAlpha>();
    frame->alpha->update(f.camera.eye, frame->settings.k);
  }));
  p.push_back(functionPass("compose", [frame](FrameContext& f) { composeViewDependent(f, *frame->alpha, frame->settings); }));
  return p;
}

}  // namespace tlab::render
