#include "study/run/camera_navigator.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tlab::study {
namespace {

render::Camera startCamera() {
  render::Camera c;
  c.eye = {0.0f, 0.0f, 5.0f};
  c.target = {0.0f, 0.0f, 0.0f};
  return c;
}

double elevationDegrees(const render::Camera& c) {
  const glm::vec3 d = glm::normalize(c.eye - c.target);
  return glm::degrees(std::asin(double(d.y)));
}

TEST(CameraNavigator, OrbitDragKeepsTheTargetAndTheDistance) {
  CameraNavigator n(Navigation::Orbit, startCamera(), 0.5f, 0.3f);
  n.drag(100.0, 0.0);  // 30° of azimuth
  EXPECT_NEAR(glm::length(n.camera().eye - n.camera().target), 5.0, 1e-4);
  EXPECT_EQ(n.camera().target, glm::vec3(0.0f));
  const glm::vec3 e = glm::normalize(n.camera().eye);
  EXPECT_NEAR(std::acos(double(e.z)), glm::radians(30.0), 1e-4);
  EXPECT_NEAR(e.y, 0.0, 1e-5);
}

TEST(CameraNavigator, OrbitElevationStopsAtEightyDegrees) {
  CameraNavigator n(Navigation::Orbit, startCamera(), 0.5f, 0.3f);
  n.drag(0.0, -100.0);  // up by 30°
  EXPECT_NEAR(elevationDegrees(n.camera()), 30.0, 1e-3);
  for (int i = 0; i < 10; ++i) n.drag(0.0, -100.0);
  EXPECT_NEAR(elevationDegrees(n.camera()), 80.0, 1e-3);
  for (int i = 0; i < 20; ++i) n.drag(0.0, 100.0);
  EXPECT_NEAR(elevationDegrees(n.camera()), -80.0, 1e-3);
}

TEST(CameraNavigator, OrbitArrowsZoomButNeverPassTheTarget) {
  CameraNavigator n(Navigation::Orbit, startCamera(), 0.5f);
  n.move(1, 0);
  EXPECT_NEAR(n.camera().eye.z, 4.5, 1e-5);
  n.move(-2, 0);
  EXPECT_NEAR(n.camera().eye.z, 5.5, 1e-5);
  for (int i = 0; i < 40; ++i) n.move(1, 0);
  EXPECT_GT(n.camera().eye.z, 0.0f);
}

TEST(CameraNavigator, WalkMovesHorizontallyAndTurnsInFiveDegreeSteps) {
  render::Camera c = startCamera();
  c.target = {0.0f, -1.0f, 0.0f};  // looking slightly down: walking stays on the floor level
  CameraNavigator n(Navigation::Walk, c, 0.5f);
  n.move(2, 0);
  EXPECT_NEAR(n.camera().eye.z, 4.0, 1e-5);
  EXPECT_NEAR(n.camera().eye.y, 0.0, 1e-6);
  EXPECT_NEAR(n.camera().target.y, -1.0, 1e-6);
  const glm::vec3 before = n.camera().target - n.camera().eye;
  n.move(0, 1);
  const glm::vec3 after = n.camera().target - n.camera().eye;
  const glm::vec2 h0 = glm::normalize(glm::vec2(before.x, before.z)), h1 = glm::normalize(glm::vec2(after.x, after.z));
  EXPECT_NEAR(glm::degrees(std::acos(double(glm::dot(h0, h1)))), 5.0, 1e-3);
  EXPECT_GT(h1.x, 0.0f) << "positive turn is to the right";
  EXPECT_NEAR(after.y, before.y, 1e-4) << "turning keeps the pitch";
  EXPECT_EQ(n.camera().eye, glm::vec3(0.0f, 0.0f, 4.0f)) << "turning does not move";
}

TEST(CameraNavigator, WalkDragLooksAroundWithTheEyeFixed) {
  CameraNavigator n(Navigation::Walk, startCamera(), 0.5f, 0.3f);
  n.drag(0.0, -1000.0);  // look up far beyond the limit
  const glm::vec3 d = glm::normalize(n.camera().target - n.camera().eye);
  EXPECT_NEAR(glm::degrees(std::asin(double(d.y))), 80.0, 1e-3);
  EXPECT_EQ(n.camera().eye, glm::vec3(0.0f, 0.0f, 5.0f));
}

TEST(CameraNavigator, NoneIgnoresInputAndNamesParse) {
  CameraNavigator n(Navigation::None, startCamera(), 0.5f);
  n.drag(50, 50);
  n.move(3, 2);
  EXPECT_EQ(n.camera().eye, glm::vec3(0.0f, 0.0f, 5.0f));
  EXPECT_EQ(parseNavigation("orbit"), Navigation::Orbit);
  EXPECT_EQ(parseNavigation("walk"), Navigation::Walk);
  EXPECT_EQ(std::string(navigationName(Navigation::Walk)), "walk");
  EXPECT_THROW(parseNavigation("fly"), std::invalid_argument);
}

}  // namespace
}  // namespace tlab::study
