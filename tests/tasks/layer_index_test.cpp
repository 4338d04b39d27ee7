#include "tasks/layer_index/layer_index_task.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "renderer/scene/scene_source.hpp"
#include "tasks/layer_index/layer_ground_truth.hpp"
#include "tasks/ray_layer_caster.hpp"
#include "tasks/layer_index/silhouette_edges.hpp"
#include "tasks/probe_helpers.hpp"

namespace tlab::tasks {
namespace {

// The camera of the open-cylinders scene (its authored camera).
render::Camera openCylindersCamera(const render::Scene& scene) { return *scene.camera; }

// The analytic contour of the sphere |p| = r seen from `eye`: points p with p·(p − eye) = 0, a
// circle of centre eye · r²/|eye|² and radius r √(1 − r²/|eye|²) in the plane ⟂ eye.
glm::dvec3 sphereContourPoint(glm::dvec3 eye, double r, double angle) {
  const double e2 = glm::dot(eye, eye);
  const glm::dvec3 centre = eye * (r * r / e2);
  const double rho = r * std::sqrt(1.0 - r * r / e2);
  const glm::dvec3 w = glm::normalize(eye);
  const glm::dvec3 u = glm::normalize(glm::cross(w, glm::dvec3(0.0, 1.0, 0.0)));
  const glm::dvec3 v = glm::cross(w, u);
  return centre + rho * (std::cos(angle) * u + std::sin(angle) * v);
}

TEST(LayerIndex, NestedSpheresContoursLieBehindTheLargerShells) {
  // n = 3 shells of radii k/3: the contour of shell k is grazed by a ray that crosses the front of
  // every larger shell and misses every smaller one, so its layer is n − k + 1.
  const render::Scene scene = render::loadScene("builtin:nested-spheres?n=3&segments=48&rings=24");
  const render::Camera camera = render::fitCamera(scene.boundingSphere(), 1.0f, 45.0f, {0.3f, 0.4f, 1.0f});
  const ViewGeometry view(camera, 400, 400);
  const RayLayerCaster caster(scene);
  const LayerGroundTruth truth(caster, view, scene.boundingSphere().radius);
  for (int k = 1; k <= 3; ++k)
    for (const double angle : {0.3, 1.9, 4.0}) {
      const glm::dvec3 p = sphereContourPoint(view.eye(), k / 3.0, angle);
      EXPECT_EQ(truth.layerOf(p), 3 - k + 1) << "shell " << k << " angle " << angle;
    }
}

TEST(LayerIndex, NestedSpheresProbesMatchTheAnalyticLayerOfTheirShell) {
  const render::Scene scene = render::loadScene("builtin:nested-spheres?n=3&segments=48&rings=24");
  const render::Camera camera = render::fitCamera(scene.boundingSphere(), 1.0f);
  const LayerIndexTask task;
  const auto questions = task.probe({scene, camera, 400, 400, 12, 5, task.settings({})});
  ASSERT_EQ(questions.size(), 12u);
  for (const auto& q : questions) {
    const glm::dvec3 p = q.points.at(0).world;
    const int shell = int(std::lround(glm::length(p) * 3.0));  // |p| ≈ k/3 (polygon within 0.3 %)
    EXPECT_NEAR(glm::length(p) * 3.0, shell, 0.02);
    EXPECT_EQ(std::get<std::int64_t>(q.truth), 3 - shell + 1) << "question " << q.number;
  }
}

TEST(LayerIndex, OpenCylindersRimAndContourPointsHaveTheirAnalyticLayers) {
  // Eye (0, 2, 4.6): outer cylinder r = 1, y ∈ [−1, 1]; inner r = 0.55, y ∈ [−1.4, 1.4].
  const render::Scene scene = render::loadScene("builtin:open-cylinders");
  const ViewGeometry view(openCylindersCamera(scene), 512, 512);
  const RayLayerCaster caster(scene);
  const LayerGroundTruth truth(caster, view, scene.boundingSphere().radius);
  // Front of the outer top rim: nothing in front.
  EXPECT_EQ(truth.layerOf({0.0, 1.0, 1.0}), 1);
  // Back of the outer top rim: the ray passes above the outer front rim (y = 1.357 at z = 1) and
  // crosses the inner cylinder's front (y = 1.277) and back (y = 1.080) walls: layer 3.
  EXPECT_EQ(truth.layerOf({0.0, 1.0, -1.0}), 3);
  // Back of the outer bottom rim: outer front wall (y = 0.071), inner front (−0.170) and back
  // (−0.759) walls in front: layer 4.
  EXPECT_EQ(truth.layerOf({0.0, -1.0, -1.0}), 4);
  // Contour (interior silhouette) of the inner cylinder at y = 0: n ⟂ (p − eye) gives
  // x² + z² = 4.6 z with x² + z² = 0.55²; only the outer front wall is in front: layer 2.
  const double z = 0.55 * 0.55 / 4.6, x = std::sqrt(0.55 * 0.55 - z * z);
  EXPECT_EQ(truth.layerOf({x, 0.0, z}), 2);
  EXPECT_EQ(truth.layerOf({-x, 0.0, z}), 2);
  // The same contour above the outer cylinder's projection: layer 1.
  EXPECT_EQ(truth.layerOf({x, 1.35, z}), 1);
}

TEST(LayerIndex, ProbeWhereTheLayerChangesIsRejectedAsAmbiguous) {
  const render::Scene scene = render::loadScene("builtin:open-cylinders");
  const ViewGeometry view(openCylindersCamera(scene), 512, 512);
  const RayLayerCaster caster(scene);
  const LayerGroundTruth truth(caster, view, scene.boundingSphere().radius);
  // Walk up the inner cylinder's contour to where its eye ray leaves the outer front wall over the
  // outer top rim (a T-junction in the image): there the 3 × 3 pixels disagree.
  const double z = 0.55 * 0.55 / 4.6, x = std::sqrt(0.55 * 0.55 - z * z);
  double below = 0.0, above = 1.35;
  ASSERT_EQ(truth.layerOf({x, below, z}), 2);
  ASSERT_EQ(truth.layerOf({x, above, z}), 1);
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (below + above);
    (truth.layerOf({x, mid, z}) == 2 ? below : above) = mid;
  }
  const LayerVerdict atJunction = truth.verdict({x, above, z});
  EXPECT_FALSE(atJunction.unambiguous());
  EXPECT_LT(atJunction.agreeingPixels, atJunction.checkedPixels);
  // Well away from the junction the same contour is unambiguous.
  EXPECT_TRUE(truth.verdict({x, 0.0, z}).unambiguous());
  EXPECT_TRUE(truth.verdict({x, 1.38, z}).unambiguous());
}

TEST(LayerIndex, ProbesLieOnSilhouettesAndTheirPixelsAgree) {
  const render::Scene scene = render::loadScene("builtin:open-cylinders");
  const render::Camera camera = openCylindersCamera(scene);
  const LayerIndexTask task;
  const auto questions = task.probe({scene, camera, 512, 512, 10, 21, task.settings({})});
  const ViewGeometry view(camera, 512, 512);
  const RayLayerCaster caster(scene);
  const LayerGroundTruth truth(caster, view, scene.boundingSphere().radius);
  const auto edges = silhouetteEdges(weldSceneObjects(scene), view.eye());
  for (const auto& q : questions) {
    const glm::dvec3 p = q.points.at(0).world;
    // On a silhouette edge: distance to the nearest edge segment ~ 0.
    double nearest = 1e9;
    for (const auto& e : edges) {
      const glm::dvec3 d = e.p1 - e.p0;
      const double t = glm::clamp(glm::dot(p - e.p0, d) / glm::dot(d, d), 0.0, 1.0);
      nearest = std::min(nearest, glm::length(e.p0 + t * d - p));
    }
    EXPECT_LT(nearest, 1e-9);
    // Each of the 9 pixels counts the same layers in front of the probe.
    const double limit = view.depth(p) - truth.depthTolerance(p);
    const glm::ivec2 pixel(glm::floor(q.points[0].pixel));
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Ray ray = view.rayThroughPixelCenter(pixel + glm::ivec2(dx, dy));
        int inFront = 0;
        for (const auto& h : caster.hits(ray, 1e-9))
          if (h.distance * glm::dot(ray.direction, view.forward()) < limit) ++inFront;
        EXPECT_EQ(inFront + 1, std::get<std::int64_t>(q.truth)) << "question " << q.number;
      }
  }
}

TEST(LayerIndex, ClosedSphereHasOnlyContoursOpenCylinderHasBoundaries) {
  const render::Scene sphere = render::loadScene("builtin:sphere?segments=24&rings=12");
  for (const auto& e : silhouetteEdges(weldSceneObjects(sphere), {0.0, 0.0, 4.0}))
    EXPECT_EQ(e.kind, SilhouetteKind::Contour);
  const render::Scene cylinders = render::loadScene("builtin:open-cylinders?segments=24&rings=2");
  int boundary = 0;
  for (const auto& e : silhouetteEdges(weldSceneObjects(cylinders), {0.0, 2.0, 4.6}))
    boundary += e.kind == SilhouetteKind::Boundary;
  EXPECT_EQ(boundary, 4 * 24);  // two rims on each of two cylinders
}

}  // namespace
}  // namespace tlab::tasks
