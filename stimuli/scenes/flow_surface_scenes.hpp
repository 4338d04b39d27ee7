#pragma once
// The three complex integral surfaces of the study, in the roles of Carnecky et al.'s pretzel,
// bubble and toroid (Carnecky Fig. 16): stream surfaces of analytic flows that roll up into tubes
// and wrap around themselves, so that some pixels see six or more layers. Fixed by name and seed:
// the seed jitters the seed curve's end points reproducibly (SeededRandom).
#include <cstdint>

#include "renderer/scene/scene.hpp"
#include "stimuli/surfaces/advancing_front.hpp"

namespace tlab::stimuli {

struct FlowSurfaceParams {
  std::uint64_t seed = 1;
  double resolution = 1.0;      // scales the front's particle density (maxSpacing / resolution)
  double timeScale = 1.0;       // scales the integration time
};

// Hill's spherical vortex with swirl: a seed line inside the sphere winds around the vortex core
// ring like a pretzel.
render::Scene pretzelScene(const FlowSurfaceParams& params);
// The swirling jet: a seed line across the axis upstream twists into a helicoid and wraps the
// vortex-breakdown bubble.
render::Scene bubbleScene(const FlowSurfaceParams& params);
// The vortex ring: a seed line through the core rolls up into a spiral tube around the ring.
render::Scene toroidScene(const FlowSurfaceParams& params);

// The surface as a scene object (name, orange front / blue back, Transparent).
render::SceneObject integralSurfaceObject(const std::string& name, const IntegralSurface& surface);

}  // namespace tlab::stimuli
