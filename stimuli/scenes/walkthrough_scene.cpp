#include "stimuli/scenes/walkthrough_scene.hpp"

#include <algorithm>
#include <numeric>
#include <regex>
#include <stdexcept>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "core/seeded_random.hpp"
#include "stimuli/scenes/shape_primitives.hpp"
#include "stimuli/scenes/walkthrough_objects.hpp"

namespace tlab::stimuli {

namespace {

constexpr float kWallHalfThickness = 0.06f;
constexpr float kDoorWidth = 1.2f;
constexpr float kDoorHeight = 2.1f;

// A wall from a to b along x (alongX) or z at height [0, h], with an optional centred doorway.
void appendWall(render::TriangleMesh& walls, glm::vec2 a, float length, bool alongX, float h, bool door) {
  const auto segment = [&](float from, float to, float y0, float y1) {
    const float mid = 0.5f * (from + to), half = 0.5f * (to - from);
    const glm::vec3 center = alongX ? glm::vec3(a.x + mid, 0.5f * (y0 + y1), a.y) : glm::vec3(a.x, 0.5f * (y0 + y1), a.y + mid);
    const glm::vec3 extent = alongX ? glm::vec3(half, 0.5f * (y1 - y0), kWallHalfThickness) : glm::vec3(kWallHalfThickness, 0.5f * (y1 - y0), half);
    appendMesh(walls, placed(render::makeBox(extent), center));
  };
  if (!door) return segment(0.0f, length, 0.0f, h);
  const float d0 = 0.5f * (length - kDoorWidth), d1 = 0.5f * (length + kDoorWidth);
  segment(0.0f, d0, 0.0f, h);
  segment(d1, length, 0.0f, h);
  segment(d0, d1, kDoorHeight, h);  // the lintel
}

render::SceneObject structure(std::string name, render::TriangleMesh mesh, glm::vec4 color, render::Role roles) {
  render::SceneObject o;
  o.name = std::move(name);
  o.mesh = std::move(mesh);
  o.frontColor = o.backColor = color;
  o.roles = roles;
  return o;
}

// The multiset of kinds: 1 trophy, 6–10 of the counted kind, the rest spread over the other kinds
// with at least two of each (so only the trophy is unique).
std::vector<std::string> chooseKinds(core::SeededRandom& random, const WalkthroughParams& p) {
  std::vector<std::string> others;
  for (const auto& k : walkthroughObjectKinds())
    if (k != "trophy" && k != p.countedKind) others.push_back(k);
  const int counted = 6 + int(random.below(5));
  if (p.objects < 1 + counted + 2 * int(others.size()))
    throw std::invalid_argument("walkthrough: " + std::to_string(p.objects) + " objects are too few for every kind");
  std::vector<std::string> kinds{"trophy"};
  for (int i = 0; i < counted; ++i) kinds.push_back(p.countedKind);
  for (const auto& k : others) kinds.insert(kinds.end(), 2, k);
  while (int(kinds.size()) < p.objects) kinds.push_back(others[random.below(std::uint32_t(others.size()))]);
  return kinds;
}

// Seed 004 Sec. VI (Fig. 7): the participant starts in the centre of the floor plan at eye height,
// looking along the floor (−z, "up" on the floor plan). With an even number of rooms the centre
// is a wall corner, so the eye stands in the middle of the room just below-right of it.
render::Camera firstPersonCamera(const WalkthroughFloorPlan& plan, float wallHeight) {
  constexpr float kEyeHeight = 1.7f;
  const float s = float(plan.roomSize());
  render::Camera c;
  c.eye = glm::vec3((float(plan.columns() / 2) + 0.5f) * s, std::min(kEyeHeight, 0.85f * wallHeight),
                    (float(plan.rows() / 2) + 0.5f) * s);
  c.target = c.eye + glm::vec3(0.0f, 0.0f, -1.0f);
  c.up = {0.0f, 1.0f, 0.0f};
  c.fovyDegrees = 60.0f;
  c.nearPlane = 0.05f;
  c.farPlane = 1.5f * s * float(std::max(plan.columns(), plan.rows()));
  return c;
}

}  // namespace

WalkthroughFloorPlan walkthroughFloorPlan(const WalkthroughParams& p) { return WalkthroughFloorPlan::random(p.seed, p.columns, p.rows); }

render::Scene walkthroughScene(const WalkthroughParams& p) {
  const WalkthroughFloorPlan plan = walkthroughFloorPlan(p);
  const float s = float(plan.roomSize()), h = float(p.wallHeight);
  const float width = s * float(plan.columns()), depth = s * float(plan.rows());
  render::Scene scene;
  scene.name = "walkthrough";
  render::TriangleMesh walls;
  for (int j = 0; j < plan.rows(); ++j)
    for (int i = 0; i < plan.columns(); ++i) {
      const glm::vec2 corner(float(i) * s, float(j) * s);
      if (i == 0) appendWall(walls, corner, s, false, h, false);
      if (j == 0) appendWall(walls, corner, s, true, h, false);
      appendWall(walls, corner + glm::vec2(s, 0), s, false, h, i + 1 < plan.columns() && plan.doorEast(i, j));
      appendWall(walls, corner + glm::vec2(0, s), s, true, h, j + 1 < plan.rows() && plan.doorSouth(i, j));
    }
  scene.objects.push_back(structure("floor", render::makeQuad({0.5f * width, 0, 0.5f * depth}, {0, 0, 0.5f * depth}, {0.5f * width, 0, 0}),
                                    {0.85f, 0.82f, 0.75f, 1}, render::Role::Opaque | render::Role::Distractor | render::Role::Impenetrable));
  scene.objects.push_back(structure("walls", std::move(walls), {0.8f, 0.8f, 0.85f, 1}, render::Role::Transparent | render::Role::Distractor));
  scene.objects.push_back(structure("ceiling", render::makeQuad({0.5f * width, h, 0.5f * depth}, {0.5f * width, 0, 0}, {0, 0, 0.5f * depth}),
                                    {0.9f, 0.9f, 0.95f, 1}, render::Role::Transparent | render::Role::Distractor));
  // Objects in distinct rooms: a partial Fisher–Yates shuffle of the rooms.
  core::SeededRandom random(p.seed * 7919u + 13u);
  const std::vector<std::string> kinds = chooseKinds(random, p);
  std::vector<int> rooms(std::size_t(plan.columns() * plan.rows()));
  std::iota(rooms.begin(), rooms.end(), 0);
  if (kinds.size() > rooms.size()) throw std::invalid_argument("walkthrough: more objects than rooms");
  std::map<std::string, int> numbers;
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    std::swap(rooms[k], rooms[k + random.below(std::uint32_t(rooms.size() - k))]);
    const int room = rooms[k];
    // z's offset is drawn before x's: the order of the first (GCC) builds, which drew both as one
    // call's arguments, whose order C++ leaves unspecified (clang drew x first).
    const float dz = random.uniform(-0.6f, 0.6f);
    const float dx = random.uniform(-0.6f, 0.6f);
    const glm::vec3 at((float(room % plan.columns()) + 0.5f) * s + dx, 0.0f, (float(room / plan.columns()) + 0.5f) * s + dz);
    const WalkthroughObjectModel model = makeWalkthroughObject(kinds[k]);
    const render::Role roles = kinds[k] == "trophy" ? render::Role::Opaque | render::Role::Target : render::Role::Opaque;
    scene.objects.push_back(structure(kinds[k] + "-" + std::to_string(++numbers[kinds[k]]),
                                      placed(model.mesh, at, random.uniform(0.0f, 6.2831853f)), model.color, roles));
  }
  scene.camera = firstPersonCamera(plan, float(p.wallHeight));
  scene.revealAllObjects = true;  // seed 004 Sec. VI: "all objects are made visible through the walls"
  return scene;
}

std::optional<core::Image> walkthroughFloorPlanForSource(const std::string& source) {
  static const std::regex pattern(R"(^builtin:walkthrough(\?.*)?$)");
  std::smatch m;
  if (!std::regex_match(source, m, pattern)) return std::nullopt;
  WalkthroughParams params;
  static const std::regex seed(R"([?&]seed=(\d+))");
  std::smatch s;
  const std::string query = m[1].str();
  if (std::regex_search(query, s, seed)) params.seed = std::stoull(s[1].str());
  return floorPlanImage(walkthroughFloorPlan(params));
}

}  // namespace tlab::stimuli
