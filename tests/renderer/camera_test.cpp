#include <gtest/gtest.h>

#include <cmath>

#include "renderer/scene/camera.hpp"

using namespace tlab::render;

TEST(Camera, ParseOverridesOnlyTheGivenFields) {
  Camera base;
  const Camera c = parseCamera("eye=1,2,3 fovy=30", base);
  EXPECT_EQ(c.eye, glm::vec3(1, 2, 3));
  EXPECT_EQ(c.target, base.target);
  EXPECT_FLOAT_EQ(c.fovyDegrees, 30.0f);
}

TEST(Camera, ParseErrorsNameTheField) {
  Camera base;
  for (const char* bad : {"eye=1,2", "fovy=abc", "zoom=2", "eye", "fovy=190", "eye=0,0,0 target=0,0,0"}) {
    try {
      parseCamera(bad, base);
      FAIL() << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("--camera"), std::string::npos) << e.what();
    }
  }
}

TEST(Camera, FitKeepsTheSphereInsideTheView) {
  const BoundingSphere sphere{{1, 2, 3}, 2.0f};
  const Camera c = fitCamera(sphere, 2.0f, 45.0f);
  // The angle subtended by the sphere is inside both half fields of view.
  const float distance = glm::length(c.eye - sphere.center);
  EXPECT_LT(std::asin(sphere.radius / distance), glm::radians(22.5f));
  EXPECT_LT(c.nearPlane, distance - sphere.radius);
  EXPECT_GT(c.farPlane, distance + sphere.radius);
}

TEST(Camera, OrbitKeepsTheDistance) {
  Camera c;
  c.eye = {0, 0, 5};
  const Camera o = orbit(c, 90.0f, 30.0f);
  EXPECT_NEAR(glm::length(o.eye - o.target), 5.0f, 1e-5f);
  EXPECT_NEAR(o.eye.y, 5.0f * std::sin(glm::radians(30.0f)), 1e-4f);
}
