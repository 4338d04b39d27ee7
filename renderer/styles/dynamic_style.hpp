#pragma once
#include <map>
#include <string>

#include <glm/glm.hpp>

#include "renderer/styles/style.hpp"

namespace tlab::render {

// `dynamic`: dynamic transparency (Elmqvist et al., seed 004). Distractors are drawn as solids
// (front-most surfaces only) in back-to-front group order; every surface in front of a target
// (Role::Target) or inside its gradient border becomes see-through through an alpha mask
// (outline, circle or ellipse); Role::Impenetrable objects are never see-through and hide what is
// behind them. Passive mode uncovers all targets, active mode only inside a lens; max_layers
// limits how many layers are uncovered. The group order is frame-coherent state owned by the
// Renderer (FrameContext::drawOrder).
class DynamicStyle final : public Style {
 public:
  std::string name() const override { return "dynamic"; }
  std::string description() const override {
    return "Elmqvist 2008: targets seen through solid distractors by an outline alpha mask (passive or lens)";
  }
  std::vector<ParamSpec> params() const override;
  FragmentProperties properties(const StyleParams& params, const SceneFacts& facts) const override;
  void validate(const StyleParams& params) const override;
  std::vector<std::unique_ptr<RenderPass>> passes(const StyleParams& params) const override;
};

// Puts the active-mode lens into a request's settings (what a window runner calls each frame
// with the cursor): `centre` in fractions of the image, (0, 0) = top left; `radius` a fraction of
// the image height. Sets mode=active.
void setDynamicLens(std::map<std::string, std::string>& settings, glm::vec2 centre, float radius);

}  // namespace tlab::render
