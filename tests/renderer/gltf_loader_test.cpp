#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "renderer/scene/gltf_loader.hpp"
#include "renderer/scene/scene_source.hpp"

using namespace tlab::render;

namespace {

// One triangle (0,0,0) (1,0,0) (0,1,0), 36 bytes of float positions, as a base64 data URI.
const char* kTriangleBuffer = "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";

std::string gltfWithNodes(const std::string& nodes, const std::string& sceneNodes, int positionCount = 3) {
  return std::string(R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":)") + sceneNodes + R"(}],"nodes":)" + nodes +
         R"(,"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"accessors":[{"bufferView":0,"componentType":5126,"count":)" +
         std::to_string(positionCount) + R"(,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36,"uri":")" +
         kTriangleBuffer + R"("}]})";
}

Scene loadText(const std::string& text) {
  return loadGltfFromMemory(std::vector<unsigned char>(text.begin(), text.end()), "test.gltf", false);
}

}  // namespace

TEST(GltfLoader, NestedNodeTransformsCompose) {
  // parent: translate (2,0,0); child: translate (0,1,0) then scale 2 → world = T(2,0,0)·T(0,1,0)·S(2).
  const Scene s = loadText(gltfWithNodes(R"([{"translation":[2,0,0],"children":[1]},{"translation":[0,1,0],"scale":[2,2,2],"mesh":0}])", "[0]"));
  ASSERT_EQ(s.objects.size(), 1u);
  const auto& p = s.objects[0].mesh.positions;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0], glm::vec3(2, 1, 0));
  EXPECT_EQ(p[1], glm::vec3(4, 1, 0));
  EXPECT_EQ(p[2], glm::vec3(2, 3, 0));
  // Normals were missing: computed, facing +z for this counter-clockwise triangle.
  EXPECT_NEAR(s.objects[0].mesh.normals[0].z, 1.0f, 1e-6f);
}

TEST(GltfLoader, MatrixAndRotationTransforms) {
  // A 90-degree rotation about z (quaternion x,y,z,w = 0,0,sin45,cos45) maps (1,0,0) to (0,1,0).
  const Scene s = loadText(gltfWithNodes(R"([{"rotation":[0,0,0.70710678,0.70710678],"mesh":0}])", "[0]"));
  EXPECT_NEAR(s.objects[0].mesh.positions[1].x, 0.0f, 1e-6f);
  EXPECT_NEAR(s.objects[0].mesh.positions[1].y, 1.0f, 1e-6f);
  const Scene m = loadText(gltfWithNodes(R"([{"matrix":[1,0,0,0, 0,1,0,0, 0,0,1,0, 5,6,7,1],"mesh":0}])", "[0]"));
  EXPECT_EQ(m.objects[0].mesh.positions[0], glm::vec3(5, 6, 7));
}

TEST(GltfLoader, NoTrianglesIsAnError) {
  // A node without a mesh: the scene has no triangles.
  try {
    loadText(gltfWithNodes(R"([{"translation":[2,0,0]}])", "[0]"));
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no triangles"), std::string::npos) << e.what();
  }
}

TEST(GltfLoader, BrokenFilesGiveOneLineErrorsNamingTheFile) {
  const auto dir = std::filesystem::temp_directory_path() / "tlab_gltf_test";
  std::filesystem::create_directories(dir);
  const auto notGltf = (dir / "notes.txt").string();
  std::ofstream(notGltf) << "hello";
  const auto broken = (dir / "broken.gltf").string();
  std::ofstream(broken) << "{ this is not json";
  for (const std::string& path : {std::string("/nonexistent/scene.gltf"), notGltf, broken}) {
    try {
      loadScene(path);
      FAIL() << path;
    } catch (const std::exception& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path, 0), 0u) << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
  }
  // An accessor that reads past its buffer is rejected, not read out of bounds.
  EXPECT_THROW(loadText(gltfWithNodes(R"([{"mesh":0}])", "[0]", 4)), std::runtime_error);
}
