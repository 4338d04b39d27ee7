#pragma once
// Dynamic transparency (Elmqvist et al., seed 004) on the illustration buffer: the target
// coverage pass (compose/dynamic_coverage.comp), the alpha mask built from it on the host
// (ops/alpha_mask), and the compositing pass (compose/dynamic_compose.comp).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/ops/alpha_mask.hpp"
#include "renderer/frame/frame_context.hpp"

namespace tlab::render {

struct DynamicSettings {
  AlphaMaskSettings mask;
  bool active = false;          // Sec. III.5: passive (whole view) or active (a lens)
  glm::vec2 lensCentre{0.5f};   // fractions of the image width and height, (0, 0) = top left
  float lensRadius = 0.2f;      // fraction of the image height
  int maxLayers = 0;            // Sec. III.6 layer control; 0: unlimited
  bool sharedStacking = false;  // see compose/dynamic_compose.comp; false: the paper's (1 − α_T)^k
  enum class Targets { Scene, Role, All } targets = Targets::Scene;
  // Role::Target only, or every object not a distractor/impenetrable (Targets::Scene: as the scene says).
  bool allAreTargets(const Scene& scene) const {
    return targets == Targets::All || (targets == Targets::Scene && scene.revealAllObjects);
  }
};

// The alpha mask of this frame (seed 004, Alg. 2): which pixels targets are drawn on
// (compose/dynamic_coverage.comp), reduced to the mask grid and grown by the border on the host.
// `drawRanks[o]`: object o's position in the back-to-front group order (ops/group_draw_order).
AlphaMask buildDynamicMask(FrameContext& frame, const std::vector<std::uint32_t>& drawRanks, const DynamicSettings& settings);

// Composes the frame into frame.image with the mask of the same frame.
void composeDynamic(FrameContext& frame, const std::vector<std::uint32_t>& drawRanks, const AlphaMask& mask,
                    const DynamicSettings& settings);

}  // namespace tlab::render
