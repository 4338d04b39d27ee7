#include "stimuli/scenes/flow_surface_scenes.hpp"

#include "renderer/pipeline/renderer.hpp"
#include "core/seeded_random.hpp"
#include "stimuli/fields/hills_spherical_vortex.hpp"
#include "stimuli/fields/swirling_jet.hpp"
#include "stimuli/fields/vortex_ring.hpp"

namespace tlab::stimuli {

namespace {

// A reproducible jitter of a seed point, at most `amount` per coordinate; z is drawn first, then y
// and x (see seedLine).
glm::dvec3 jitter(core::SeededRandom& random, const glm::dvec3& p, double amount) {
  return p + amount * glm::dvec3(random.pointZFirst(-1.0f, 1.0f));
}

// The seed line from a to b, each end jittered, b's first. C++ leaves the order of a call's
// arguments unspecified (GCC evaluates them last to first, clang first to last), and the first
// builds drew these as one call's arguments: each draw is now its own statement, in the order of
// those (GCC) builds, so the surfaces made since stay byte-identical and a clang build makes the
// same ones.
SeedCurve seedLine(core::SeededRandom& random, const glm::dvec3& a, const glm::dvec3& b, double amount) {
  const glm::dvec3 end = jitter(random, b, amount);
  const glm::dvec3 start = jitter(random, a, amount);
  return SeedCurve::line(start, end);
}

IntegratorSettings surfaceIntegrator() {
  IntegratorSettings s;
  s.kind = IntegratorKind::DormandPrince;
  s.step = 0.01;
  s.absoluteTolerance = 1e-7;
  s.relativeTolerance = 1e-7;
  return s;
}

AdvancingFrontSettings frontSettings(double maxSpacing, double timeStep, double duration, const FlowSurfaceParams& p) {
  AdvancingFrontSettings f;
  f.maxSpacing = maxSpacing / p.resolution;
  f.minSpacing = 0.3 * f.maxSpacing;
  f.timeStep = timeStep;
  f.steps = std::max(1, int(duration * p.timeScale / timeStep + 0.5));
  f.maxParticles = std::size_t(1500 * p.resolution);
  return f;
}

// The bounding sphere of the vertices that triangles use (particles that left the domain or
// tore off keep their last vertices, which must not pull the view away).
render::BoundingSphere surfaceBounds(const render::TriangleMesh& mesh) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const auto& t : mesh.triangles)
    for (const auto v : t) lo = glm::min(lo, mesh.positions[v]), hi = glm::max(hi, mesh.positions[v]);
  const glm::vec3 center = 0.5f * (lo + hi);
  float radius = 0.0f;
  for (const auto& t : mesh.triangles)
    for (const auto v : t) radius = std::max(radius, glm::distance(center, mesh.positions[v]));
  return {center, radius};
}

render::Scene surfaceScene(const std::string& name, const IntegralSurface& surface, glm::vec3 viewDirection) {
  render::Scene scene;
  scene.name = name;
  scene.objects.push_back(integralSurfaceObject(name, surface));
  scene.camera = render::fitCamera(surfaceBounds(surface.mesh), 1.0f, 40.0f, glm::normalize(viewDirection));
  scene.camera = render::fitClipPlanes(*scene.camera, scene.boundingSphere());
  return scene;
}

}  // namespace

render::SceneObject integralSurfaceObject(const std::string& name, const IntegralSurface& surface) {
  render::SceneObject object;
  object.name = name;
  object.mesh = surface.mesh;
  object.frontColor = {0.95f, 0.6f, 0.2f, 1.0f};
  object.backColor = {0.25f, 0.5f, 0.9f, 1.0f};
  object.roles = render::Role::Transparent;
  return object;
}

render::Scene pretzelScene(const FlowSurfaceParams& p) {
  core::SeededRandom random(p.seed);
  const HillsSphericalVortex field({1.0, 1.0, 1.5});
  const SeedCurve seed = seedLine(random, {0.3, 0.0, -0.3}, {0.8, 0.0, 0.3}, 0.03);
  const IntegralSurface surface = streamSurface(field, seed, 0.0, surfaceIntegrator(), frontSettings(0.035, 0.04, 9.6, p));
  return surfaceScene("pretzel", surface, {0.3f, 1.0f, 0.6f});
}

render::Scene bubbleScene(const FlowSurfaceParams& p) {
  core::SeededRandom random(p.seed);
  const SwirlingJet field;
  const SeedCurve seed = seedLine(random, {-0.6, 0.08, -2.6}, {0.6, 0.08, -2.6}, 0.03);
  const IntegralSurface surface = streamSurface(field, seed, 0.0, surfaceIntegrator(), frontSettings(0.05, 0.04, 5.0, p));
  return surfaceScene("bubble", surface, {1.0f, 0.3f, 0.2f});
}

render::Scene toroidScene(const FlowSurfaceParams& p) {
  core::SeededRandom random(p.seed);
  const VortexRing field({1.0, 0.35, 4.0, 0.0, 2.0, 1.6});  // particles streaming away leave the domain
  const SeedCurve seed = seedLine(random, {0.7, 0.0, -0.03}, {1.3, 0.0, 0.03}, 0.02);
  const IntegralSurface surface = streamSurface(field, seed, 0.0, surfaceIntegrator(), frontSettings(0.06, 0.025, 4.5, p));
  return surfaceScene("toroid", surface, {0.4f, 0.5f, 1.0f});
}

}  // namespace tlab::stimuli
