#pragma once
// Elmqvist's ABSTRACT world (seed 004, Sec. VI.4): a 100 × 100 × 100 cube filled with 200 random
// spheres, cones, boxes and tori (intersections allowed, no object enclosing another); 10–20 % are
// red targets (Role::Target), the others random green or blue. Object names are "<kind>-<n>".
//
// The T2 variant: red cones (the targets) stand on the cells of a 5 × 7 letter rotated about the
// vertical axis, among red distractors of other shapes (Role::Distractor) and green/blue objects.
// The letter's cells come from the caller (the tasks library owns the bitmaps; see
// abstractPatternSpec in stimulus_scenes.hpp).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/scene.hpp"

namespace tlab::stimuli {

struct AbstractWorldParams {
  std::uint64_t seed = 1;
  int objects = 200;
  double worldSize = 100.0;
  double minTargetShare = 0.10;
  double maxTargetShare = 0.20;
};

render::Scene abstractWorldScene(const AbstractWorldParams& params);

struct AbstractPatternParams {
  std::uint64_t seed = 1;
  int objects = 200;             // all objects, letter cones included
  int redDistractors = 12;
  double worldSize = 100.0;
  double cellSize = 9.0;         // letter grid spacing
};

// `letterCells`: the filled (column, row) cells of the 5 × 7 bitmap, row 0 = top line.
render::Scene abstractPatternScene(const AbstractPatternParams& params, const std::vector<glm::ivec2>& letterCells);

// Whether every vertex of `inner` lies inside the bounding sphere of `outer` (a necessary
// condition for `outer` to enclose `inner`; false proves that it does not).
bool insideBoundingSphere(const render::TriangleMesh& inner, const render::TriangleMesh& outer);

}  // namespace tlab::stimuli
