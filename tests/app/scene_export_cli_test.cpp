// End-to-end: `tlab scene export` writes a scene another renderer can draw from tlab's camera —
// the glTF's camera, roles and image size as the README states them, and tlab itself drawing the
// exported file from that camera covering exactly the pixels it covers for the built-in scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"

using namespace tlab::testing;

namespace {

const std::string kTlab = TLAB_EXE;

// The samples of a binary 16-bit PGM (P5 W H 65535).
std::vector<int> pgmSamples(const std::string& path) {
  const std::string bytes = readText(path);
  std::size_t at = 0;
  for (int fields = 0; fields < 4; ++fields) {  // magic, width, height, maxval
    while (at < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[at]))) ++at;
    while (at < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[at]))) ++at;
  }
  ++at;
  std::vector<int> samples;
  for (; at + 1 < bytes.size(); at += 2) samples.push_back((std::uint8_t(bytes[at]) << 8) | std::uint8_t(bytes[at + 1]));
  return samples;
}

}  // namespace

TEST(SceneExportCli, TheExportedCameraRolesAndSizeAreTlabs) {
  const auto dir = freshDir("scene_export");
  const auto gltf = (dir / "walk.gltf").string();
  const auto r = runCommand(kTlab + " scene export builtin:abstract --size 120x90 -o " + gltf);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto doc = nlohmann::json::parse(readText(gltf));
  EXPECT_EQ(doc["asset"]["version"], "2.0");
  const auto& scene = doc["scenes"][0];
  EXPECT_EQ(scene["extras"]["tlab_image_size"], nlohmann::json::array({120, 90}));
  const auto& cameraNode = doc["nodes"].back();
  ASSERT_EQ(cameraNode["name"], "tlab-camera");
  const auto& perspective = doc["cameras"][cameraNode["camera"].get<int>()]["perspective"];
  const double fovy = scene["extras"]["tlab_camera"]["fovy_degrees"];
  EXPECT_NEAR(perspective["yfov"].get<double>(), fovy * M_PI / 180.0, 1e-6);
  EXPECT_NEAR(perspective["aspectRatio"].get<double>(), 120.0 / 90.0, 1e-9);
  // The node's world matrix puts the eye at its origin (column-major: translation in 12..14).
  const auto& eye = scene["extras"]["tlab_camera"]["eye"];
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(cameraNode["matrix"][12 + k].get<double>(), eye[k].get<double>(), 1e-4);
  // Elmqvist's ABSTRACT world: red transparent targets among transparent others; the roles travel
  // in the extras.
  int targets = 0, others = 0;
  for (const auto& node : doc["nodes"])
    if (node.contains("extras")) {
      const auto& roles = node["extras"]["tlab_roles"];
      const bool target = std::find(roles.begin(), roles.end(), "target") != roles.end();
      EXPECT_NE(std::find(roles.begin(), roles.end(), "transparent"), roles.end()) << node["name"];
      (target ? targets : others) += 1;
    }
  EXPECT_GT(targets, 0);
  EXPECT_GT(others, targets);
}

TEST(SceneExportCli, TlabDrawsTheExportedFileAsTheBuiltInScene) {
  const auto dir = freshDir("scene_export_roundtrip");
  const auto glb = (dir / "torus.glb").string();
  ASSERT_EQ(runCommand(kTlab + " scene export builtin:torus --size 96x72 -o " + glb).exitCode, 0);
  const auto a = (dir / "a.pgm").string(), b = (dir / "b.pgm").string();
  ASSERT_EQ(runCommand(kTlab + " render builtin:torus --size 96x72 -o " + (dir / "a.png").string() + " --layers-out " + a).exitCode, 0);
  const auto drawn = runCommand(kTlab + " render " + glb + " --size 96x72 -o " + (dir / "b.png").string() + " --layers-out " + b);
  ASSERT_EQ(drawn.exitCode, 0) << drawn.err;
  const auto ours = pgmSamples(a), exported = pgmSamples(b);
  ASSERT_EQ(ours.size(), 96u * 72u);
  ASSERT_EQ(exported.size(), ours.size());
  int differ = 0, covered = 0;
  for (std::size_t i = 0; i < ours.size(); ++i) differ += ours[i] != exported[i], covered += ours[i] > 0;
  EXPECT_GT(covered, 1000);
  EXPECT_LE(differ, 3) << "pixels whose layer count differs";  // the camera re-read from a float matrix
}
