#pragma once
// Mesh pieces the seeds' scenes are built from, beyond the renderer's primitives: cones, disks,
// annuli, closed cylinders, torus arcs, and placement helpers.
#include <glm/glm.hpp>

#include "renderer/scene/triangle_mesh.hpp"

namespace tlab::stimuli {

// A closed cone along +y: base disk of `radius` at y = 0, apex at y = height.
render::TriangleMesh makeCone(float radius, float height, int segments);
// A disk of `radius` in the plane y = 0, facing +y.
render::TriangleMesh makeDisk(float radius, int segments);
// A flat ring between two radii in the plane y = 0, facing +y.
render::TriangleMesh makeAnnulus(float innerRadius, float outerRadius, int segments);
// A cylinder along y from 0 to height, with caps when `capped`.
render::TriangleMesh makeCylinder(float radius, float height, int segments, bool capped);
// Part of a torus in the xy plane about the origin: angles [from, to] (radians) of the major circle.
render::TriangleMesh makeTorusArc(float majorRadius, float minorRadius, float fromAngle, float toAngle, int majorSegments,
                                  int minorSegments);

// Returns `mesh` transformed by translate · rotateY(yaw) · rotateX(pitch) · scale.
render::TriangleMesh placed(render::TriangleMesh mesh, glm::vec3 position, float yawRadians = 0.0f, float pitchRadians = 0.0f,
                            glm::vec3 scale = glm::vec3(1.0f));

}  // namespace tlab::stimuli
