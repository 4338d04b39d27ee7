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

// A camera no look-at or perspective matrix can be built from is refused with the reason (each
// used to be accepted and gave a picture of NaNs: the first was found by fuzz/render_options).
TEST(Camera, AViewNoMatrixCanHoldIsRefused) {
  const Camera base;  // eye 0,0,3, target 0,0,0, up 0,1,0
  const auto error = [&](const char* text) {
    try {
      parseCamera(text, base);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(error("eye=0,2.2,0"),  // looking straight down with the default up 0,1,0
            "--camera field 'up': points along the line of sight from eye to target; give one across it");
  EXPECT_EQ(error("up=0,0,-2"), "--camera field 'up': points along the line of sight from eye to target; give one across it");
  EXPECT_EQ(error("up=0,0,0"), "--camera field 'up': must not be zero");
  EXPECT_EQ(error("up=3e38,3e38,0"), "--camera field 'up': too long for a float (give a direction)");
  EXPECT_EQ(error("eye=1e300,0,0"), "--camera field 'eye': '1e300' is beyond a float's range");
  EXPECT_EQ(error("eye=3e38,0,0 target=-3e38,0,0"), "--camera: eye and target are too far apart");
  EXPECT_EQ(error("eye=0,0,1e-30"), "--camera: eye and target are too close together for a float");
  EXPECT_EQ(error("up=1e-22,1e-22,0"), "--camera: no view a float can hold from this eye, target and up (give up as a direction about 1 long)");
  EXPECT_EQ(error("near=1 far=3e38"), "--camera: near and far give no projection (they lie too far apart for a float)");
  // Looking down is fine with an up across the line of sight, and so is an up of any length a float can square.
  EXPECT_EQ(parseCamera("eye=0,2.2,0 up=0,0,-1", base).up, glm::vec3(0, 0, -1));
  EXPECT_EQ(parseCamera("up=0,1e15,0", base).up, glm::vec3(0, 1e15f, 0));
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
