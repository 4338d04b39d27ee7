#include "study/run/frame_log.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "core/sha256.hpp"

namespace tlab::study {
namespace {

TEST(FrameLog, JsonReadsBackEveryFloatExactly) {
  LiveFrame f;
  f.index = 7;
  f.camera.eye = {0.1f, -2.0f / 3.0f, 3.14159274f};
  f.camera.target = {1e-7f, 0.0f, -0.3f};
  f.camera.up = {0.0f, 1.0f, 0.0f};
  f.camera.fovyDegrees = 47.5f;
  f.camera.nearPlane = 0.0123f;
  f.camera.farPlane = 987.6f;
  f.lens = glm::vec2(1.0f / 3.0f, 0.7f);
  f.input = "drag 3,-1";
  f.shownNs = 1234567890123;
  f.sha256 = std::string(64, 'a');
  const LiveFrame g = parseFrameJson(frameJson(f));
  EXPECT_EQ(g.index, 7);
  EXPECT_EQ(g.camera.eye, f.camera.eye);
  EXPECT_EQ(g.camera.target, f.camera.target);
  EXPECT_EQ(g.camera.up, f.camera.up);
  EXPECT_EQ(g.camera.fovyDegrees, f.camera.fovyDegrees);
  EXPECT_EQ(g.camera.nearPlane, f.camera.nearPlane);
  EXPECT_EQ(g.camera.farPlane, f.camera.farPlane);
  ASSERT_TRUE(g.lens.has_value());
  EXPECT_EQ(*g.lens, *f.lens);
  EXPECT_EQ(g.input, f.input);
  EXPECT_EQ(g.shownNs, f.shownNs);
  EXPECT_EQ(g.sha256, f.sha256);
  EXPECT_EQ(g.encoding, "") << "no encoding: shown as rendered (the window)";
  EXPECT_EQ(frameJson(f).find("encoding"), std::string::npos);
  f.lens.reset();
  EXPECT_FALSE(parseFrameJson(frameJson(f)).lens.has_value());
}

// A frame sent lossy says so in its event ([online] frames = "jpeg"); its hash is still the pixels'.
TEST(FrameLog, TheEncodingAFrameWasSentInReadsBack) {
  LiveFrame f;
  f.sha256 = std::string(64, 'b');
  f.encoding = "jpeg quality=75";
  EXPECT_NE(frameJson(f).find(R"("encoding":"jpeg quality=75")"), std::string::npos) << frameJson(f);
  EXPECT_EQ(parseFrameJson(frameJson(f)).encoding, "jpeg quality=75");
}

TEST(FrameLog, BadJsonNamesTheField) {
  try {
    parseFrameJson(R"({"index":0,"camera":"eye=0,0,3","input":"start","shown_ns":1})");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sha256"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parseFrameJson("[1,2]"), std::invalid_argument);
  EXPECT_THROW(parseFrameJson(R"({"index":"x","camera":"eye=0,0,3","input":"","shown_ns":1,"sha256":"")"), std::invalid_argument);
}

TEST(FrameLog, PixelHashCoversSizeAndEveryByte) {
  Canvas a(2, 3, {10, 20, 30, 255});
  Canvas b(3, 2, {10, 20, 30, 255});  // same bytes, other shape
  EXPECT_NE(framePixelsSha256(a), framePixelsSha256(b));
  Canvas c = a;
  EXPECT_EQ(framePixelsSha256(a), framePixelsSha256(c));
  c.blend(1, 2, {11, 20, 30, 255}, 255);
  EXPECT_NE(framePixelsSha256(a), framePixelsSha256(c));
  // "2x3:" followed by 24 bytes, computed independently of framePixelsSha256's code path.
  std::string bytes = "2x3:";
  for (int i = 0; i < 6; ++i) bytes += std::string{char(10), char(20), char(30), char(255)};
  EXPECT_EQ(framePixelsSha256(a), core::sha256Hex(std::string_view(bytes)));
}

}  // namespace
}  // namespace tlab::study
