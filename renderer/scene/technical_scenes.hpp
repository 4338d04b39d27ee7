#pragma once
// Built-in scenes of technical illustration (Diepstraten et al. 2002, Sec. 7 and colour plate):
// `mug-box` (a transparent mug with an explicitly modelled inner wall around an opaque box),
// `crank-cylinder` (an opaque crank inside a transparent cylinder) and `mugs` (several
// transparent mugs). Solids are closed, outward-facing surfaces of revolution.
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/builtin_scenes.hpp"

namespace tlab::render {

const std::vector<BuiltinSceneSpec>& technicalScenes();

// A closed surface of revolution about the y axis from a profile of (radius, height) points,
// traversed counter-clockwise in the (r, y) half-plane (so the solid lies to its left). Each
// profile segment is its own ring of faces with its own normals (hard edges between segments).
TriangleMesh makeLathe(const std::vector<glm::vec2>& profile, int segments);

// A mug as one solid: outer wall and bottom, rim, and the explicitly modelled inner wall and
// inner bottom (Diepstraten Fig. 6). Standing on y = 0.
TriangleMesh makeMug(float outerRadius, float innerRadius, float height, float bottomThickness, int segments);

// A closed cylinder from `a` to `b`.
TriangleMesh makeCappedCylinder(glm::vec3 a, glm::vec3 b, float radius, int segments);

}  // namespace tlab::render
