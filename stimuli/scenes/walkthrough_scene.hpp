#pragma once
// Elmqvist's WALKTHROUGH world (seed 004, Sec. VI.4): the rooms of a WalkthroughFloorPlan with
// walls (doorways cut out), floor and ceiling, and 50 objects in distinct rooms — one unique
// trophy (Role::Target, the T3 target), a counted kind (T4, "chair" by default) appearing
// 6–10 times, and the other kinds at least twice each. Names are "<kind>-<n>".
// The structure is Role::Distractor (walls and ceiling may be see-through, dynamic style with
// targets=all uncovers every placed object as in the paper); the floor is also Role::Impenetrable
// (Sec. V.2: no target is ever behind it).
#include <cstdint>
#include <optional>
#include <string>

#include "renderer/scene/scene.hpp"
#include "stimuli/scenes/walkthrough_floor_plan.hpp"

namespace tlab::stimuli {

struct WalkthroughParams {
  std::uint64_t seed = 1;
  int columns = 16;
  int rows = 16;
  int objects = 50;
  std::string countedKind = "chair";
  double wallHeight = 2.5;
};

// The floor plan the scene of `params` is built on (the same seed gives the same plan).
WalkthroughFloorPlan walkthroughFloorPlan(const WalkthroughParams& params);
render::Scene walkthroughScene(const WalkthroughParams& params);

// For `builtin:walkthrough[?seed=S...]`: the floor-plan image of that scene; nothing otherwise.
std::optional<core::Image> walkthroughFloorPlanForSource(const std::string& source);

}  // namespace tlab::stimuli
