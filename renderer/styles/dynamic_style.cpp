#include "renderer/styles/dynamic_style.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "renderer/compose/dynamic_compositor.hpp"
#include "renderer/ops/group_draw_order.hpp"

namespace tlab::render {

namespace {

DynamicSettings settingsFrom(const StyleParams& p) {
  DynamicSettings s;
  s.mask.size = int(p.number("mask_size"));
  s.mask.border = int(p.number("border"));
  s.mask.alphaTarget = float(p.number("alpha_target"));
  s.mask.alpha0 = float(p.number("alpha_0"));
  s.mask.shape = parseMaskShape(p.choice("mask"));
  s.active = p.is("mode", "active");
  s.lensCentre = {float(p.number("lens_x")), float(p.number("lens_y"))};
  s.lensRadius = float(p.number("lens_radius"));
  s.maxLayers = int(p.number("max_layers"));
  s.sharedStacking = p.is("stacking", "shared");
  s.targets = p.is("targets", "all")    ? DynamicSettings::Targets::All
              : p.is("targets", "role") ? DynamicSettings::Targets::Role
                                        : DynamicSettings::Targets::Scene;
  return s;
}

struct DynamicFrame {
  DynamicSettings settings;
  std::vector<std::uint32_t> ranks;
  AlphaMask mask;
};

void requireInteger(const StyleParams& p, const std::string& key) {
  const double v = p.number(key);
  if (v != std::floor(v)) throw std::invalid_argument("style 'dynamic': " + key + " must be a whole number, got " + p.values().at(key));
}

}  // namespace

std::vector<ParamSpec> DynamicStyle::params() const {
  return {
      ParamSpec::choice("mode", "passive", {"passive", "active"},
                        "passive: uncover every target; active: only inside the lens (Sec. III.5)"),
      ParamSpec::choice("mask", "outline", {"outline", "circle", "ellipse"}, "alpha mask shape (Fig. 2)"),
      ParamSpec::number("mask_size", 0, 0, 4096,
                        "alpha mask cells per side; 0: the image's resolution with the border scaled to n/128 of "
                        "the image (no grid blocks); 128: the paper's grid (Sec. V.4)"),
      ParamSpec::number("border", 4, 0, 64,
                        "n: width of the gradient border in mask cells (Algs. 2-3); mask_size=0: in cells of the "
                        "paper's 128-cell grid"),
      ParamSpec::number("alpha_target", 0.35, 0, 1, "alpha_T: opacity of surfaces in front of a target"),
      ParamSpec::number("alpha_0", 0.15, 0, 1, "alpha_0: opacity where the border gradient starts (rises to 1)"),
      ParamSpec::number("lens_x", 0.5, 0, 1, "active mode: lens centre, fraction of the width from the left"),
      ParamSpec::number("lens_y", 0.5, 0, 1, "active mode: lens centre, fraction of the height from the top"),
      ParamSpec::number("lens_radius", 0.2, 0.001, 2, "active mode: lens radius, fraction of the image height"),
      ParamSpec::number("max_layers", 0, 0, 64, "layer control: most layers uncovered in front of a target (0: unlimited)"),
      ParamSpec::choice("stacking", "multiply", {"multiply", "shared"},
                        "each occluder of a target gets alpha_T, (1-alpha_T)^k behind k (paper), or they share it "
                        "(weight 1-alpha_T at any depth)"),
      ParamSpec::choice("targets", "scene", {"scene", "role", "all"},
                        "targets: as the scene says (walkthrough: all objects), objects with the target role, or all "
                        "objects not flagged distractor or impenetrable"),
  };
}

FragmentProperties DynamicStyle::properties(const StyleParams&, const SceneFacts&) const {
  FragmentProperties p;
  p |= FragmentProperty::Color;
  p |= FragmentProperty::Ids;
  return p;
}

void DynamicStyle::validate(const StyleParams& params) const {
  for (const char* key : {"mask_size", "border", "max_layers"}) requireInteger(params, key);
  const double size = params.number("mask_size");
  if (size > 0 && size < 8)
    throw std::invalid_argument("style 'dynamic': mask_size must be 0 (the image's resolution) or at least 8, got " +
                                params.values().at("mask_size"));
}

std::vector<std::unique_ptr<RenderPass>> DynamicStyle::passes(const StyleParams& params) const {
  auto frame = std::make_shared<DynamicFrame>();
  frame->settings = settingsFrom(params);
  std::vector<std::unique_ptr<RenderPass>> p;
  // Alg. 1 line 1: re-sort the groups back to front for this frame's camera (the frame-coherent
  // bubble sort on the Renderer's GroupDrawOrder).
  p.push_back(functionPass("order", [frame](FrameContext& f) {
    if (!f.drawOrder) throw std::logic_error("the dynamic style needs the renderer's group draw order");
    f.drawOrder->update(f.camera.eye, f.camera.target - f.camera.eye);
    frame->ranks = f.drawOrder->objectRanks();
  }));
  // Alg. 2: the alpha mask from where targets are drawn.
  p.push_back(functionPass("mask", [frame](FrameContext& f) { frame->mask = buildDynamicMask(f, frame->ranks, frame->settings); }));
  // Alg. 1 lines 2-7 and Sec. V.3: the surfaces blended back to front through the mask.
  p.push_back(functionPass("compose", [frame](FrameContext& f) { composeDynamic(f, frame->ranks, frame->mask, frame->settings); }));
  return p;
}

void setDynamicLens(std::map<std::string, std::string>& settings, glm::vec2 centre, float radius) {
  settings["mode"] = "active";
  settings["lens_x"] = std::to_string(std::clamp(centre.x, 0.0f, 1.0f));
  settings["lens_y"] = std::to_string(std::clamp(centre.y, 0.0f, 1.0f));
  settings["lens_radius"] = std::to_string(std::clamp(radius, 0.001f, 2.0f));
}

}  // namespace tlab::render
