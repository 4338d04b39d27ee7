// The seeds' procedural scenes: Elmqvist's ABSTRACT world and its T2 letter pattern, the
// WALKTHROUGH floor plan and objects, and the catalog.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "renderer/scene/scene_source.hpp"
#include "stimuli/scenes/abstract_world.hpp"
#include "stimuli/scenes/stimulus_scenes.hpp"
#include "stimuli/scenes/walkthrough_objects.hpp"
#include "stimuli/scenes/walkthrough_scene.hpp"
#include "tasks/letter_patterns.hpp"
#include "tasks/scene_targets.hpp"

namespace tlab::stimuli {
namespace {

bool isRed(const glm::vec4& c) { return c.r > 0.7f && c.g < 0.3f && c.b < 0.3f; }

TEST(AbstractWorld, HasTwoHundredObjectsTenToTwentyPercentRedTargetsAndNoEnclosure) {
  for (const std::uint64_t seed : {1u, 2u}) {
    AbstractWorldParams params;
    params.seed = seed;
    const render::Scene scene = abstractWorldScene(params);
    ASSERT_EQ(scene.objects.size(), 200u);
    std::size_t targets = 0;
    std::set<std::string> kinds;
    for (const auto& o : scene.objects) {
      const bool target = render::hasRole(o.roles, render::Role::Target);
      targets += target ? 1 : 0;
      EXPECT_EQ(target, isRed(o.frontColor)) << o.name;  // targets are exactly the red objects
      if (!target) { EXPECT_TRUE(o.frontColor.g > 0.6f || o.frontColor.b > 0.8f) << o.name << " is neither green nor blue"; }
      kinds.insert(tasks::objectKind(o.name));
      for (const auto& p : o.mesh.positions) {
        EXPECT_GE(std::min({p.x, p.y, p.z}), 0.0f);
        EXPECT_LE(std::max({p.x, p.y, p.z}), 100.0f);
      }
    }
    EXPECT_GE(targets, 20u);
    EXPECT_LE(targets, 40u);
    EXPECT_EQ(kinds, (std::set<std::string>{"sphere", "cone", "box", "torus"}));
    // No object encloses another: some vertex of each lies outside the other's bounding sphere.
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      for (std::size_t j = 0; j < scene.objects.size(); ++j)
        if (i != j) { ASSERT_FALSE(insideBoundingSphere(scene.objects[i].mesh, scene.objects[j].mesh)) << i << " in " << j; }
  }
}

TEST(AbstractWorld, IsFixedBySeed) {
  AbstractWorldParams a, b;
  b.seed = 2;
  const render::Scene a1 = abstractWorldScene(a), a2 = abstractWorldScene(a), b1 = abstractWorldScene(b);
  ASSERT_EQ(a1.objects.size(), a2.objects.size());
  for (std::size_t i = 0; i < a1.objects.size(); ++i) {
    EXPECT_EQ(a1.objects[i].name, a2.objects[i].name);
    EXPECT_EQ(a1.objects[i].mesh.positions, a2.objects[i].mesh.positions);
  }
  EXPECT_NE(a1.objects[0].mesh.positions, b1.objects[0].mesh.positions);
}

TEST(AbstractPattern, TheRedConesFormExactlyTheRequestedLetter) {
  const render::BuiltinSceneSpec spec = abstractPatternSpec(tasks::patternLetters(), tasks::letterCells);
  for (std::size_t i = 0; i < tasks::patternLetters().size(); ++i)
    for (const int seed : {1, 7}) {
      const char letter = tasks::patternLetters()[i];
      const render::Scene scene =
          render::buildBuiltinScene("abstract-pattern?letter=" + std::to_string(i) + "&seed=" + std::to_string(seed), {spec});
      ASSERT_EQ(scene.objects.size(), 200u);
      std::vector<glm::dvec2> floor;
      std::size_t redDistractors = 0;
      for (const auto& o : scene.objects) {
        if (render::hasRole(o.roles, render::Role::Target)) {
          EXPECT_EQ(tasks::objectKind(o.name), "cone");
          EXPECT_TRUE(isRed(o.frontColor));
          floor.push_back(tasks::floorPlanPoint(tasks::surfaceCentroid(o.mesh)));
        } else if (isRed(o.frontColor)) {
          EXPECT_NE(tasks::objectKind(o.name), "cone") << "red distractors have other shapes";
          EXPECT_TRUE(render::hasRole(o.roles, render::Role::Distractor));
          ++redDistractors;
        }
      }
      EXPECT_EQ(floor.size(), tasks::letterCells(letter).size()) << letter;
      EXPECT_EQ(tasks::matchingLetters(floor), std::vector<char>{letter}) << letter << " seed " << seed;
      EXPECT_EQ(redDistractors, 12u);
    }
}

TEST(WalkthroughFloorPlan, EveryRoomIsReachable) {
  for (const std::uint64_t seed : {1u, 2u, 3u, 42u}) {
    const WalkthroughFloorPlan plan = WalkthroughFloorPlan::random(seed);
    EXPECT_EQ(plan.columns(), 16);
    EXPECT_EQ(plan.rows(), 16);
    EXPECT_EQ(plan.reachableRooms(), 256u);
    EXPECT_GE(plan.doorCount(), 255u);  // a spanning tree has 255 doorways; extras make loops
    EXPECT_GT(plan.doorCount(), 255u);
  }
}

TEST(WalkthroughFloorPlan, ReachabilityCountsOnlyConnectedRooms) {
  // Without extra doors the plan is a tree: removing nothing keeps 256; a 1-room plan is trivial.
  const WalkthroughFloorPlan single = WalkthroughFloorPlan::random(1, 1, 1);
  EXPECT_EQ(single.reachableRooms(), 1u);
  EXPECT_EQ(single.doorCount(), 0u);
}

TEST(WalkthroughFloorPlan, ImageShowsWallsWithDoorwayGaps) {
  const WalkthroughFloorPlan plan = WalkthroughFloorPlan::random(5);
  const core::Image image = floorPlanImage(plan, 32);
  EXPECT_EQ(image.width, 16 * 32 + 32);
  std::size_t black = 0;
  for (const auto& p : image.pixels) black += p.r < 0.5f ? 1 : 0;
  EXPECT_GT(black, 1000u);
  EXPECT_LT(black, image.pixels.size() / 3);
  // The outer wall is closed: the left border column is black from top to bottom of the rooms.
  for (int y = 16; y < 16 + 16 * 32; ++y) EXPECT_LT(image.at(16, y).r, 0.5f);
}

TEST(WalkthroughScene, DefaultCameraIsFirstPersonInTheCentreAtEyeHeight) {
  // Seed 004 Sec. VI / Fig. 7: the participant starts in the centre of the floor plan at eye height.
  const render::Scene scene = walkthroughScene(WalkthroughParams{});
  ASSERT_TRUE(scene.camera.has_value());
  const render::Camera& c = *scene.camera;
  EXPECT_NEAR(c.eye.y, 1.7f, 1e-6f);
  EXPECT_LT(std::abs(c.eye.x - 32.0f), 4.0f);  // within the room next to the centre of 16 × 4 m
  EXPECT_LT(std::abs(c.eye.z - 32.0f), 4.0f);
  EXPECT_NEAR(c.target.y, c.eye.y, 1e-6f);     // looking along the floor
  EXPECT_TRUE(scene.revealAllObjects);         // "all objects are made visible through the walls"
}

TEST(WalkthroughScene, HasFiftyObjectsOneUniqueTargetAndACountedKind) {
  WalkthroughParams params;
  params.seed = 9;
  const render::Scene scene = walkthroughScene(params);
  std::map<std::string, int> kinds;
  std::size_t targets = 0;
  for (std::size_t i = 3; i < scene.objects.size(); ++i) {
    kinds[tasks::objectKind(scene.objects[i].name)]++;
    targets += render::hasRole(scene.objects[i].roles, render::Role::Target) ? 1 : 0;
  }
  EXPECT_EQ(scene.objects.size(), 53u);  // floor, walls, ceiling + 50 objects
  EXPECT_EQ(scene.objects[1].name, "walls");
  EXPECT_EQ(targets, 1u);
  // Dynamic transparency roles: the structure is distractor, the floor also impenetrable.
  for (std::size_t i = 0; i < 3; ++i) EXPECT_TRUE(render::hasRole(scene.objects[i].roles, render::Role::Distractor));
  EXPECT_TRUE(render::hasRole(scene.objects[0].roles, render::Role::Impenetrable));
  for (std::size_t i = 3; i < scene.objects.size(); ++i)
    EXPECT_FALSE(render::hasRole(scene.objects[i].roles, render::Role::Distractor | render::Role::Impenetrable));
  EXPECT_EQ(kinds["trophy"], 1);
  EXPECT_GE(kinds["chair"], 6);
  EXPECT_LE(kinds["chair"], 10);
  for (const auto& [kind, n] : kinds)
    if (kind != "trophy") { EXPECT_GE(n, 2) << kind; }
  EXPECT_EQ(kinds.size(), walkthroughObjectKinds().size());
  EXPECT_EQ(tasks::selectTargets(scene, "").size(), 1u);
  EXPECT_EQ(int(tasks::selectTargets(scene, "chair").size()), kinds["chair"]);
  // Objects stand inside the building, in distinct rooms.
  std::set<std::pair<int, int>> rooms;
  for (std::size_t i = 3; i < scene.objects.size(); ++i) {
    const glm::dvec3 c = tasks::surfaceCentroid(scene.objects[i].mesh);
    rooms.insert({int(c.x / 4.0), int(c.z / 4.0)});
  }
  EXPECT_EQ(rooms.size(), 50u);
}

TEST(WalkthroughScene, FloorPlanForASourceMatchesTheScenesSeed) {
  EXPECT_FALSE(walkthroughFloorPlanForSource("builtin:abstract").has_value());
  const auto a = walkthroughFloorPlanForSource("builtin:walkthrough?seed=5");
  ASSERT_TRUE(a.has_value());
  WalkthroughParams p;
  p.seed = 5;
  EXPECT_EQ(a->pixels, floorPlanImage(walkthroughFloorPlan(p)).pixels);
}

TEST(StimulusScenes, EverySceneBuildsFromTheCatalogWithTriangles) {
  const auto specs = allSceneSpecs({abstractPatternSpec(tasks::patternLetters(), tasks::letterCells)});
  for (const char* name : {"pretzel", "bubble", "toroid", "abstract", "abstract-pattern", "walkthrough"}) {
    const render::Scene scene = render::loadScene(std::string("builtin:") + name, specs);
    EXPECT_GT(scene.triangleCount(), 100u) << name;
    EXPECT_TRUE(scene.camera.has_value()) << name;
  }
  EXPECT_THROW(render::loadScene("builtin:pretzel?seed=-1", specs), std::exception);
}

TEST(FlowSurfaces, AreFixedByNameAndSeed) {
  const auto specs = allSceneSpecs();
  const render::Scene a = render::loadScene("builtin:toroid?seed=3", specs);
  const render::Scene b = render::loadScene("builtin:toroid?seed=3", specs);
  const render::Scene c = render::loadScene("builtin:toroid?seed=4", specs);
  EXPECT_EQ(a.objects[0].mesh.positions, b.objects[0].mesh.positions);
  EXPECT_NE(a.objects[0].mesh.positions, c.objects[0].mesh.positions);
}

}  // namespace
}  // namespace tlab::stimuli
