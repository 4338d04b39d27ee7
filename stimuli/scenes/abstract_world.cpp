#include "stimuli/scenes/abstract_world.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "core/seeded_random.hpp"
#include "stimuli/scenes/shape_primitives.hpp"

namespace tlab::stimuli {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
const glm::vec4 kRed{0.85f, 0.1f, 0.1f, 1.0f};

enum class ShapeKind { Sphere, Cone, Box, Torus };
const char* kindName(ShapeKind k) {
  switch (k) {
    case ShapeKind::Sphere: return "sphere";
    case ShapeKind::Cone: return "cone";
    case ShapeKind::Box: return "box";
    case ShapeKind::Torus: return "torus";
  }
  return "?";
}

// C++ leaves the order of a call's arguments unspecified (GCC evaluates them last to first, clang
// first to last). Where the first builds drew several values as one call's arguments, each draw is
// now its own statement in the order those (GCC) builds drew them: the worlds made since stay
// byte-identical, and a clang build makes the same ones.

// A random orientation (yaw, pitch), the pitch drawn first.
std::pair<float, float> randomTurn(core::SeededRandom& random) {
  const float pitch = random.uniform(0.0f, kPi);
  const float yaw = random.uniform(0.0f, kPi);
  return {yaw, pitch};
}

// A random position in the cube [0, size]³, z drawn first.
glm::vec3 randomPoint(core::SeededRandom& random, float size) { return random.pointZFirst(0.0f, size); }

// A random primitive of `kind`, centred at the origin, randomly oriented (cones stay upright).
render::TriangleMesh randomShape(core::SeededRandom& random, ShapeKind kind) {
  switch (kind) {
    case ShapeKind::Sphere: return render::makeUvSphere(random.uniform(2.5f, 6.0f), 24, 12);
    case ShapeKind::Cone: {
      const float h = random.uniform(6.0f, 12.0f);
      return placed(makeCone(random.uniform(2.5f, 5.0f), h, 24), {0, -0.5f * h, 0});
    }
    case ShapeKind::Box: {
      const auto [yaw, pitch] = randomTurn(random);
      const glm::vec3 size{random.uniform(1.5f, 5.0f), random.uniform(1.5f, 5.0f), random.uniform(1.5f, 5.0f)};
      return placed(render::makeBox(size), {0, 0, 0}, yaw, pitch);
    }
    case ShapeKind::Torus: {
      const float major = random.uniform(3.0f, 6.0f);
      const auto [yaw, pitch] = randomTurn(random);
      return placed(render::makeTorus(major, random.uniform(0.8f, 0.35f * major), 32, 12), {0, 0, 0}, yaw, pitch);
    }
  }
  return {};
}

glm::vec4 greenOrBlue(core::SeededRandom& random) {
  return random.below(2) == 0 ? glm::vec4(0.15f, 0.7f, 0.25f, 1.0f) : glm::vec4(0.15f, 0.35f, 0.9f, 1.0f);
}

render::BoundingSphere meshBounds(const render::TriangleMesh& mesh) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const auto& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::vec3 c = 0.5f * (lo + hi);
  float r = 0.0f;
  for (const auto& p : mesh.positions) r = std::max(r, glm::distance(p, c));
  return {c, r};
}

// Places objects one after the other, rejecting candidates that would enclose or be enclosed.
class WorldBuilder {
 public:
  WorldBuilder(render::Scene& scene, double worldSize) : scene_(scene), size_(float(worldSize)) {}

  bool fits(const render::TriangleMesh& mesh) const {
    const glm::vec3 lo(0.0f), hi(size_);
    for (const auto& p : mesh.positions)
      if (glm::any(glm::lessThan(p, lo)) || glm::any(glm::greaterThan(p, hi))) return false;
    return std::none_of(scene_.objects.begin(), scene_.objects.end(), [&](const render::SceneObject& o) {
      return insideBoundingSphere(mesh, o.mesh) || insideBoundingSphere(o.mesh, mesh);
    });
  }

  // Tries random positions until the shape fits; returns false after many failures.
  bool addRandom(core::SeededRandom& random, ShapeKind kind, glm::vec4 color, render::Role roles) {
    for (int attempt = 0; attempt < 200; ++attempt) {
      const render::TriangleMesh shape = randomShape(random, kind);
      const glm::vec3 at = randomPoint(random, size_);
      render::TriangleMesh mesh = placed(shape, at);
      if (fits(mesh)) {
        add(kind, std::move(mesh), color, roles);
        return true;
      }
    }
    return false;
  }

  void add(ShapeKind kind, render::TriangleMesh mesh, glm::vec4 color, render::Role roles) {
    render::SceneObject o;
    o.name = std::string(kindName(kind)) + "-" + std::to_string(++counts_[int(kind)]);
    o.mesh = std::move(mesh);
    o.frontColor = o.backColor = color;
    o.roles = roles;
    scene_.objects.push_back(std::move(o));
  }

 private:
  render::Scene& scene_;
  float size_;
  int counts_[4] = {0, 0, 0, 0};
};

void requireCount(const render::Scene& scene, int wanted) {
  if (int(scene.objects.size()) != wanted)
    throw std::runtime_error(scene.name + ": could place only " + std::to_string(scene.objects.size()) + " of " + std::to_string(wanted) +
                             " objects without enclosure");
}

void withCamera(render::Scene& scene, double worldSize, glm::vec3 direction) {
  const float half = float(worldSize) / 2.0f;
  const render::BoundingSphere cube{glm::vec3(half), half * std::sqrt(3.0f)};
  scene.camera = render::fitClipPlanes(render::fitCamera(cube, 1.0f, 45.0f, glm::normalize(direction)), cube);
}

}  // namespace

bool insideBoundingSphere(const render::TriangleMesh& inner, const render::TriangleMesh& outer) {
  const render::BoundingSphere s = meshBounds(outer);
  return std::all_of(inner.positions.begin(), inner.positions.end(), [&](const glm::vec3& p) { return glm::distance(p, s.center) <= s.radius; });
}

render::Scene abstractWorldScene(const AbstractWorldParams& p) {
  core::SeededRandom random(p.seed);
  render::Scene scene;
  scene.name = "abstract";
  const int lo = int(std::ceil(p.minTargetShare * p.objects)), hi = int(std::floor(p.maxTargetShare * p.objects));
  const int targets = lo + int(random.below(std::uint32_t(hi - lo + 1)));
  WorldBuilder builder(scene, p.worldSize);
  for (int i = 0; i < p.objects; ++i) {
    const ShapeKind kind = ShapeKind(random.below(4));
    const bool target = i < targets;
    const glm::vec4 color = target ? kRed : greenOrBlue(random);
    const render::Role roles = target ? render::Role::Transparent | render::Role::Target : render::Role::Transparent;
    builder.addRandom(random, kind, color, roles);
  }
  requireCount(scene, p.objects);
  withCamera(scene, p.worldSize, {0.6f, 0.5f, 1.0f});
  return scene;
}

render::Scene abstractPatternScene(const AbstractPatternParams& p, const std::vector<glm::ivec2>& cells) {
  core::SeededRandom random(p.seed);
  render::Scene scene;
  scene.name = "abstract-pattern";
  WorldBuilder builder(scene, p.worldSize);
  // The letter: cell (c, r) at origin + R(angle)·(c − 2, r − 3)·cellSize on the floor plan (x, z),
  // rotated about the vertical axis (x, z) → (x cos a + z sin a, −x sin a + z cos a).
  const float angle = random.uniform(0.0f, 2.0f * kPi), ca = std::cos(angle), sa = std::sin(angle);
  const float half = float(p.worldSize) / 2.0f, cell = float(p.cellSize);
  for (const auto& c : cells) {
    const glm::vec2 local = glm::vec2(float(c.x) - 2.0f, float(c.y) - 3.0f) * cell;
    const glm::vec2 floor(local.x * ca + local.y * sa, -local.x * sa + local.y * ca);
    const float height = random.uniform(0.35f, 0.65f) * float(p.worldSize);
    builder.add(ShapeKind::Cone, placed(makeCone(2.5f, 7.0f, 24), {half + floor.x, height, half + floor.y}), kRed,
                render::Role::Transparent | render::Role::Target);
  }
  const ShapeKind others[] = {ShapeKind::Sphere, ShapeKind::Box, ShapeKind::Torus};
  for (int i = 0; i < p.redDistractors; ++i)
    builder.addRandom(random, others[random.below(3)], kRed, render::Role::Transparent | render::Role::Distractor);
  while (int(scene.objects.size()) < p.objects) {
    const glm::vec4 color = greenOrBlue(random);  // before the kind (see randomTurn)
    if (!builder.addRandom(random, others[random.below(3)], color, render::Role::Transparent)) break;
  }
  requireCount(scene, p.objects);
  withCamera(scene, p.worldSize, {0.2f, 1.2f, 0.6f});
  return scene;
}

}  // namespace tlab::stimuli
