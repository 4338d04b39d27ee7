// The floor plan: clicks map back to the world floor position they show, and the plan sits
// beside the stimulus on the screen.
#include <gtest/gtest.h>

#include "renderer/scene/builtin_scenes.hpp"
#include "study/run/floor_plan.hpp"
#include "study/window/screen_layout.hpp"

using namespace tlab::study;

TEST(FloorPlan, PixelAndWorldRoundTripOnTheFloor) {
  tlab::render::Scene scene;
  tlab::render::SceneObject floor;
  floor.mesh = tlab::render::makeBox({10.0f, 0.5f, 6.0f});
  scene.objects.push_back(floor);
  const FloorPlan plan = makeFloorPlan(scene, 200, 100);
  EXPECT_DOUBLE_EQ(plan.floorY, -0.5);
  for (const glm::dvec2 xz : {glm::dvec2(0, 0), glm::dvec2(7.5, -3), glm::dvec2(-9, 5.5)}) {
    const glm::dvec2 pixel = plan.pixelOf({xz.x, plan.floorY, xz.y});
    EXPECT_GE(pixel.x, 0.0);
    EXPECT_LE(pixel.x, 200.0);
    EXPECT_GE(pixel.y, 0.0);
    EXPECT_LE(pixel.y, 100.0);
    const glm::dvec2 back = plan.worldAt(pixel);
    EXPECT_NEAR(back.x, xz.x, 1e-6);
    EXPECT_NEAR(back.y, xz.y, 1e-6);
  }
  // North (−z) is at the top and east (+x) on the right of the plan.
  EXPECT_LT(plan.pixelOf({0, plan.floorY, -5}).y, plan.pixelOf({0, plan.floorY, 5}).y);
  EXPECT_LT(plan.pixelOf({-5, plan.floorY, 0}).x, plan.pixelOf({5, plan.floorY, 0}).x);
}

TEST(ScreenLayout, StimulusFitsAndPlanSitsBesideIt) {
  const ScreenLayout l = makeScreenLayout(640, 480, 160, 160);
  EXPECT_EQ(l.stimulus.width, l.stimulus.height);
  EXPECT_GE(l.stimulus.y, l.header.height);
  EXPECT_LE(l.stimulus.y + l.stimulus.height, l.answer.y);
  const glm::dvec2 corner = l.toScreen({160, 160});
  EXPECT_NEAR(corner.x, l.stimulus.x + l.stimulus.width, 1e-9);
  EXPECT_NEAR(l.toStimulus(l.toScreen({37.5, 80.25})).x, 37.5, 1e-9);
  const ScreenLayout p = makeScreenLayoutWithPlan(640, 480, 160, 160);
  ASSERT_TRUE(p.plan);
  EXPECT_EQ(p.plan->width, p.stimulus.width);
  EXPECT_GT(p.plan->x, p.stimulus.x + p.stimulus.width);
  EXPECT_EQ(hitPoint({{10, 10}, {30, 10}}, {27, 12}), 1);
  // Shown at the rendered size or a whole multiple (here 1x; 2x in a large window), never resampled by a fraction.
  EXPECT_EQ(l.stimulus.width, 160);
  EXPECT_EQ(makeScreenLayout(1024, 900, 160, 160).stimulus.width, 4 * 160);
  EXPECT_EQ(makeScreenLayout(1024, 768, 240, 240).stimulus.width, 2 * 240);
  EXPECT_EQ(hitPoint({{10, 10}}, {60, 60}), -1);
}
