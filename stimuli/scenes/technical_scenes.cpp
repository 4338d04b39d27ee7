#include "stimuli/scenes/technical_scenes.hpp"

#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/scene/seeded_random.hpp"
#include "stimuli/scenes/shape_primitives.hpp"

namespace tlab::stimuli {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

render::SceneObject transparentObject(std::string name, render::TriangleMesh mesh, glm::vec4 front, glm::vec4 back) {
  render::SceneObject o;
  o.name = std::move(name);
  o.mesh = std::move(mesh);
  o.frontColor = front;
  o.backColor = back;
  o.roles = render::Role::Transparent;
  return o;
}

render::SceneObject opaqueObject(std::string name, render::TriangleMesh mesh, glm::vec4 color) {
  render::SceneObject o;
  o.name = std::move(name);
  o.mesh = std::move(mesh);
  o.frontColor = o.backColor = color;
  o.roles = render::Role::Opaque | render::Role::Impenetrable;
  return o;
}

// Flips a mesh inside out (for inner walls, whose front faces the mug's axis).
render::TriangleMesh flipped(render::TriangleMesh mesh) {
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  for (auto& n : mesh.normals) n = -n;
  return mesh;
}

void withCamera(render::Scene& scene, glm::vec3 direction) {
  const render::BoundingSphere sphere = scene.boundingSphere();
  scene.camera = render::fitClipPlanes(render::fitCamera(sphere, 1.0f, 40.0f, glm::normalize(direction)), sphere);
}

}  // namespace

render::TriangleMesh makeMug(float radius, float height, float wall, int segments) {
  // The inner wall starts at the inner bottom (y = wall): shift it up.
  render::TriangleMesh innerWall = flipped(makeCylinder(radius - wall, height - wall, segments, false));
  transformMesh(innerWall, glm::translate(glm::mat4(1.0f), {0, wall, 0}));
  render::TriangleMesh result = makeCylinder(radius, height, segments, false);
  appendMesh(result, innerWall);
  appendMesh(result, placed(makeAnnulus(radius - wall, radius, segments), {0, height, 0}));                 // rim
  appendMesh(result, placed(makeDisk(radius, segments), {0, 0, 0}, 0.0f, kPi));                              // outer bottom (faces −y)
  appendMesh(result, placed(makeDisk(radius - wall, segments), {0, wall, 0}));                                // inner bottom
  // The handle: a torus arc on the +x side in the xy plane.
  const float handleRadius = 0.3f * height;
  appendMesh(result, placed(makeTorusArc(handleRadius, 0.35f * wall + 0.02f, -0.5f * kPi, 0.5f * kPi, 24, 12),
                            {radius - 0.05f * radius, 0.5f * height, 0}));
  return result;
}

render::Scene mugBoxScene() {
  render::Scene scene;
  scene.name = "mug-box";
  scene.objects.push_back(transparentObject("mug", makeMug(1.0f, 2.0f, 0.12f, 96), {0.95f, 0.65f, 0.3f, 1}, {0.3f, 0.55f, 0.9f, 1}));
  scene.objects.push_back(opaqueObject("box", placed(render::makeBox({0.35f, 0.3f, 0.35f}), {0.0f, 0.45f, 0.0f}, 0.5f), {0.8f, 0.15f, 0.15f, 1}));
  withCamera(scene, {0.7f, 0.6f, 1.0f});
  return scene;
}

render::Scene mugsScene(std::uint64_t seed, int count) {
  render::SeededRandom random(seed);
  render::Scene scene;
  scene.name = "mugs";
  for (int i = 0; i < count; ++i) {
    const float radius = random.uniform(0.7f, 1.1f), height = random.uniform(1.5f, 2.4f);
    const glm::vec3 at(2.4f * float(i % 3) + random.uniform(-0.4f, 0.4f), 0.0f, -1.9f * float(i / 3) + random.uniform(-0.4f, 0.4f));
    const float hue = float(i) / float(count);
    scene.objects.push_back(transparentObject("mug-" + std::to_string(i + 1),
                                              placed(makeMug(radius, height, 0.1f, 72), at, random.uniform(0.0f, 2.0f * kPi)),
                                              {0.95f, 0.5f + 0.3f * hue, 0.25f, 1}, {0.25f, 0.45f + 0.3f * hue, 0.9f, 1}));
  }
  withCamera(scene, {0.3f, 0.5f, 1.0f});
  return scene;
}

render::Scene crankCylinderScene() {
  render::Scene scene;
  scene.name = "crank-cylinder";
  // The housing: a closed transparent cylinder along x.
  scene.objects.push_back(transparentObject("housing", placed(makeCylinder(1.0f, 4.0f, 96, true), {0.0f, -2.0f, 0.0f}),
                                            {0.7f, 0.8f, 0.95f, 1}, {0.45f, 0.55f, 0.8f, 1}));
  transformMesh(scene.objects.back().mesh, glm::rotate(glm::mat4(1.0f), -0.5f * kPi, glm::vec3(0, 0, 1)));
  // The crank shaft: main journals, two webs and the crank pin, opaque.
  render::TriangleMesh shaft = placed(makeCylinder(0.18f, 3.6f, 32, true), {0, 0, 0});
  transformMesh(shaft, glm::translate(glm::rotate(glm::mat4(1.0f), -0.5f * kPi, glm::vec3(0, 0, 1)), {0, -1.8f, 0}));
  for (const float x : {-0.45f, 0.45f}) appendMesh(shaft, placed(render::makeBox({0.08f, 0.45f, 0.25f}), {x, 0.3f, 0}));
  render::TriangleMesh pin = makeCylinder(0.14f, 0.9f, 24, true);
  transformMesh(pin, glm::translate(glm::rotate(glm::translate(glm::mat4(1.0f), {0, 0.6f, 0}), -0.5f * kPi, glm::vec3(0, 0, 1)), {0, -0.45f, 0}));
  appendMesh(shaft, pin);
  scene.objects.push_back(opaqueObject("crank", shaft, {0.55f, 0.55f, 0.6f, 1}));
  withCamera(scene, {0.5f, 0.5f, 1.0f});
  return scene;
}

}  // namespace tlab::stimuli
