#include "stimuli/scenes/walkthrough_objects.hpp"

#include <numbers>
#include <stdexcept>

#include "renderer/scene/builtin_scenes.hpp"
#include "stimuli/scenes/shape_primitives.hpp"

namespace tlab::stimuli {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
using Mesh = render::TriangleMesh;

void add(Mesh& m, const Mesh& part) { appendMesh(m, part); }
Mesh box(glm::vec3 center, glm::vec3 half) { return placed(render::makeBox(half), center); }
Mesh sphere(glm::vec3 center, float r) { return placed(render::makeUvSphere(r, 16, 8), center); }
Mesh post(glm::vec3 base, float r, float h) { return placed(makeCylinder(r, h, 10, true), base); }
Mesh wheel(glm::vec3 center, float R, float r) { return placed(render::makeTorus(R, r, 20, 8), center, 0.0f, 0.0f); }

void fourLegs(Mesh& m, float x, float z, float r, float h) {
  for (const float sx : {-x, x})
    for (const float sz : {-z, z}) add(m, post({sx, 0, sz}, r, h));
}

Mesh dog() {
  Mesh m = box({0, 0.45f, 0}, {0.35f, 0.15f, 0.14f});
  fourLegs(m, 0.25f, 0.09f, 0.04f, 0.32f);
  add(m, sphere({0.45f, 0.65f, 0}, 0.14f));
  add(m, placed(makeCone(0.04f, 0.3f, 8), {-0.35f, 0.5f, 0}, 0.0f, 0.0f));
  return m;
}
Mesh cat() {
  Mesh m = box({0, 0.25f, 0}, {0.22f, 0.09f, 0.08f});
  fourLegs(m, 0.16f, 0.05f, 0.025f, 0.18f);
  add(m, sphere({0.28f, 0.38f, 0}, 0.09f));
  for (const float z : {-0.05f, 0.05f}) add(m, placed(makeCone(0.035f, 0.08f, 8), {0.28f, 0.45f, z}));
  add(m, placed(makeCylinder(0.02f, 0.35f, 8, true), {-0.22f, 0.25f, 0}, 0.0f, -0.5f));
  return m;
}
Mesh car() {
  Mesh m = box({0, 0.35f, 0}, {0.6f, 0.15f, 0.3f});
  add(m, box({-0.05f, 0.6f, 0}, {0.32f, 0.12f, 0.27f}));
  for (const float x : {-0.38f, 0.38f})
    for (const float z : {-0.3f, 0.3f}) add(m, wheel({x, 0.17f, z}, 0.12f, 0.05f));
  return m;
}
Mesh bicycle() {
  Mesh m = wheel({-0.45f, 0.33f, 0}, 0.3f, 0.025f);
  add(m, wheel({0.45f, 0.33f, 0}, 0.3f, 0.025f));
  add(m, box({0, 0.55f, 0}, {0.45f, 0.025f, 0.025f}));
  add(m, box({-0.2f, 0.45f, 0}, {0.025f, 0.15f, 0.025f}));
  add(m, box({0.35f, 0.75f, 0}, {0.025f, 0.2f, 0.2f}));
  add(m, box({-0.2f, 0.65f, 0}, {0.1f, 0.03f, 0.05f}));
  return m;
}
Mesh chair() {
  Mesh m = box({0, 0.45f, 0}, {0.22f, 0.03f, 0.22f});
  fourLegs(m, 0.18f, 0.18f, 0.025f, 0.43f);
  add(m, box({-0.2f, 0.75f, 0}, {0.025f, 0.28f, 0.22f}));
  return m;
}
Mesh table() {
  Mesh m = box({0, 0.74f, 0}, {0.6f, 0.03f, 0.4f});
  fourLegs(m, 0.52f, 0.32f, 0.035f, 0.72f);
  return m;
}
Mesh lamp() {
  Mesh m = placed(makeCylinder(0.18f, 0.04f, 16, true), {0, 0, 0});
  add(m, post({0, 0.04f, 0}, 0.025f, 1.3f));
  add(m, placed(makeCone(0.3f, 0.35f, 16), {0, 1.25f, 0}));
  return m;
}
Mesh plant() {
  Mesh m = placed(makeCylinder(0.18f, 0.35f, 16, true), {0, 0, 0});
  add(m, sphere({0, 0.65f, 0}, 0.3f));
  add(m, sphere({0.15f, 0.9f, 0.05f}, 0.18f));
  return m;
}
Mesh bed() {
  Mesh m = box({0, 0.22f, 0}, {0.95f, 0.2f, 0.5f});
  add(m, box({-0.75f, 0.5f, 0}, {0.15f, 0.07f, 0.35f}));
  add(m, box({-0.98f, 0.45f, 0}, {0.04f, 0.45f, 0.5f}));
  return m;
}
Mesh trophy() {
  Mesh m = box({0, 0.1f, 0}, {0.18f, 0.1f, 0.18f});
  add(m, post({0, 0.2f, 0}, 0.04f, 0.3f));
  add(m, placed(makeCone(0.25f, 0.45f, 20), {0, 0.95f, 0}, 0.0f, kPi));  // the cup, upside-down cone
  for (const float x : {-0.27f, 0.27f}) add(m, wheel({x, 0.8f, 0}, 0.08f, 0.02f));
  return m;
}

}  // namespace

const std::vector<std::string>& walkthroughObjectKinds() {
  static const std::vector<std::string> kinds = {"dog", "cat", "car", "bicycle", "chair", "table", "lamp", "plant", "bed", "trophy"};
  return kinds;
}

WalkthroughObjectModel makeWalkthroughObject(const std::string& kind) {
  if (kind == "dog") return {kind, dog(), {0.55f, 0.35f, 0.2f, 1}};
  if (kind == "cat") return {kind, cat(), {0.5f, 0.5f, 0.55f, 1}};
  if (kind == "car") return {kind, car(), {0.95f, 0.8f, 0.1f, 1}};
  if (kind == "bicycle") return {kind, bicycle(), {0.1f, 0.6f, 0.6f, 1}};
  if (kind == "chair") return {kind, chair(), {0.2f, 0.3f, 0.85f, 1}};
  if (kind == "table") return {kind, table(), {0.6f, 0.45f, 0.3f, 1}};
  if (kind == "lamp") return {kind, lamp(), {0.95f, 0.95f, 0.6f, 1}};
  if (kind == "plant") return {kind, plant(), {0.2f, 0.7f, 0.25f, 1}};
  if (kind == "bed") return {kind, bed(), {0.75f, 0.4f, 0.7f, 1}};
  if (kind == "trophy") return {kind, trophy(), {0.9f, 0.15f, 0.1f, 1}};
  throw std::invalid_argument("unknown walkthrough object '" + kind + "'");
}

}  // namespace tlab::stimuli
