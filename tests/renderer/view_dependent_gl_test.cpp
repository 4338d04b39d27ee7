// View-dependent transparency (Diepstraten et al. 2002): Eq. 2 on the GPU against the CPU, and
// the rules of Sec. 4 with implicit (Sec. 6.1) and explicit (Sec. 6.2) interior boundaries.
// Colours are flat and pure so each channel tells one story: transparent faces blue, opaque red,
// background green, transparent back faces red (they must never show).
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/ops/view_dependent_alpha.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/scene/technical_scenes.hpp"
#include "tests/support/front_view_scene.hpp"
#include "tests/support/gl_fixture.hpp"

using namespace tlab::render;

namespace {

constexpr int kSize = 64;
constexpr float kAlphaOpaque = 0.6f, kAlphaBackground = 0.5f;

SceneObject shell(float radius, glm::vec3 centre) {
  SceneObject o;
  o.name = "shell";
  o.mesh = makeUvSphere(radius, 48, 24);
  transformMesh(o.mesh, glm::translate(glm::mat4(1.0f), centre));
  o.frontColor = {0, 0, 1, 1};
  o.backColor = {1, 0, 0, 1};
  o.roles = Role::Transparent;
  return o;
}

SceneObject opaqueBox(float half, glm::vec3 centre) {
  SceneObject o;
  o.name = "box";
  o.mesh = makeBox(glm::vec3(half));
  transformMesh(o.mesh, glm::translate(glm::mat4(1.0f), centre));
  o.frontColor = o.backColor = {1, 0, 0, 1};
  o.roles = Role::Opaque;
  return o;
}

Scene sceneOf(std::vector<SceneObject> objects) { return tlab::testing::frontViewScene(std::move(objects)); }

tlab::core::Image render(const Scene& scene, const std::string& boundaries) {
  Renderer renderer(scene);
  RenderRequest r;
  r.width = r.height = kSize;
  r.style = "view-dependent";
  r.settings = {{"boundaries", boundaries}, {"lines", "off"}, {"shading", "lighting"}, {"lighting", "none"},
                {"alpha_opaque", std::to_string(kAlphaOpaque)}, {"alpha_background", std::to_string(kAlphaBackground)}};
  return renderer.render(r);
}

const glm::vec4& centre(const tlab::core::Image& img) { return img.at(kSize / 2, kSize / 2); }

}  // namespace

TEST(ViewDependentAlpha, PerVertexAlphaIsEquation2OfTheDistanceToTheSilhouettes) {
  Scene scene = sceneOf({shell(1.0f, glm::vec3(0.2f, 0.0f, 0.0f)), opaqueBox(0.2f, glm::vec3(0))});
  ViewDependentAlpha alpha(scene);
  const float k = 0.7f;
  alpha.update(scene.camera->eye, k);
  const auto& a = alpha.vertexAlphaValues();
  const auto& mesh = scene.objects[0].mesh;
  glm::vec3 c(0.0f);
  for (const auto& p : mesh.positions) c += p / float(mesh.positions.size());
  float dMax = 0;
  for (const auto& p : mesh.positions) dMax = std::max(dMax, glm::length(p - c));
  const auto segments = EdgeAdjacency(mesh).silhouettes(scene.camera->eye);
  ASSERT_FALSE(segments.empty());
  for (std::size_t v = 0; v < mesh.positions.size(); v += 7) {
    float d = INFINITY;
    for (const auto& s : segments) {
      const glm::vec3 e = s.p1 - s.p0;
      const float t = glm::clamp(glm::dot(mesh.positions[v] - s.p0, e) / glm::dot(e, e), 0.0f, 1.0f);
      d = std::min(d, glm::length(mesh.positions[v] - (s.p0 + t * e)));
    }
    EXPECT_NEAR(a[v], 1.0f - std::pow(std::min(d / dMax, 1.0f), k), 1e-4f) << "vertex " << v;  // Eq. 2
  }
  // The box is opaque: α = 1 at all its vertices.
  for (std::size_t v = mesh.positions.size(); v < a.size(); ++v) EXPECT_EQ(a[v], 1.0f);
}

class DiepstratenRules : public ::testing::TestWithParam<std::string> {};

TEST_P(DiepstratenRules, AnOpaqueBoxInsideOneShellIsVisible) {
  const tlab::core::Image img = render(sceneOf({shell(1.0f, glm::vec3(0)), opaqueBox(0.3f, glm::vec3(0))}), GetParam());
  EXPECT_NEAR(centre(img).r, kAlphaOpaque, 1e-3);  // the box, with its user α
  EXPECT_NEAR(centre(img).g, 0.0f, 1e-3);          // not the background
  // The shell's front face is blended on top, most opaque towards its silhouette (Eq. 2); at the
  // centre, farther than d_max from the silhouette, α_T = 0.
  EXPECT_NEAR(centre(img).b, 0.0f, 1e-3);
  float rim = 0.0f;
  for (int x = 0; x < kSize / 2; ++x) rim = std::max(rim, img.at(x, kSize / 2).b);
  EXPECT_GT(rim, 0.3f);
}

TEST_P(DiepstratenRules, AnOpaqueBoxBehindTwoShellsIsHidden) {
  // Two shells one behind the other on the view axis, the box inside the far one.
  const tlab::core::Image side = render(sceneOf({shell(0.6f, glm::vec3(0, 0, 1.5f)), shell(1.0f, glm::vec3(0, 0, -1.0f)),
                                     opaqueBox(0.3f, glm::vec3(0, 0, -1.0f))}),
                            GetParam());
  EXPECT_NEAR(centre(side).r, 0.0f, 1e-3);
  EXPECT_NEAR(centre(side).g, kAlphaBackground, 1e-3);
  // Nested shells around the box.
  const tlab::core::Image nested =
      render(sceneOf({shell(1.0f, glm::vec3(0)), shell(0.6f, glm::vec3(0)), opaqueBox(0.3f, glm::vec3(0))}), GetParam());
  EXPECT_NEAR(centre(nested).r, 0.0f, 1e-3);
}

TEST_P(DiepstratenRules, TransparentBackFacesNeverAppear) {
  for (const Scene& scene : {sceneOf({shell(1.0f, glm::vec3(0))}),
                             sceneOf({shell(1.0f, glm::vec3(-0.5f, 0, 0)), shell(1.0f, glm::vec3(0.6f, 0.2f, -1.0f))})}) {
    const tlab::core::Image img = render(scene, GetParam());
    int covered = 0;
    for (const auto& p : img.pixels) {
      ASSERT_EQ(p.r, 0.0f);  // back faces are red; no opaque object here
      covered += p.b > 0.0f;
    }
    EXPECT_GT(covered, kSize * kSize / 10);
  }
}

INSTANTIATE_TEST_SUITE_P(Boundaries, DiepstratenRules, ::testing::Values("implicit", "explicit"));

// Sec. 6.2 against Sec. 6.1 on the mug: with the inner wall modelled explicitly, the box inside
// shows only under explicit interior boundaries (the implicit method stops at the wall's back face).
TEST(DiepstratenRules, MugWithExplicitInnerWallShowsTheBoxOnlyWithExplicitBoundaries) {
  std::map<std::string, double> p{{"segments", 64}};
  Scene scene = technicalScenes()[0].build(p);
  ASSERT_EQ(scene.name, "mug-box");
  scene.objects[0].frontColor = {0, 0, 1, 1};
  scene.objects[0].backColor = {1, 0, 0, 1};
  scene.objects[1].frontColor = scene.objects[1].backColor = {1, 0, 0, 1};
  scene.background = {0, 1, 0, 1};
  const auto redPixels = [&](const std::string& boundaries) {
    const tlab::core::Image img = render(scene, boundaries);
    int n = 0;
    for (const auto& px : img.pixels) n += px.r > 0.3f;
    return n;
  };
  EXPECT_GT(redPixels("explicit"), 40);
  // Implicit: only the box top seen through the opening (no wall in between) remains.
  EXPECT_LT(redPixels("implicit"), redPixels("explicit") / 2);
}

namespace {

// The crank scene in flat grey: every surface and the background 0.5, so a pixel brighter than
// 0.5 means blend weights summing above 1.
tlab::core::Image greyCrank(const std::string& blend) {
  Scene scene = loadScene("builtin:crank-cylinder?segments=32", technicalScenes());
  for (auto& o : scene.objects) o.frontColor = o.backColor = {0.5f, 0.5f, 0.5f, 1};
  scene.background = {0.5f, 0.5f, 0.5f, 1};
  Renderer renderer(scene);
  RenderRequest r;
  r.width = r.height = kSize;
  r.style = "view-dependent";
  r.settings = {{"boundaries", "implicit"}, {"lines", "off"}, {"shading", "lighting"}, {"lighting", "none"}, {"blend", blend}};
  return renderer.render(r);
}

}  // namespace

// Sec. 7's GL_SRC_ALPHA + GL_DST_ALPHA with α_opaque = 0.6 sums above 1 near the cylinder's
// edges (the washed-out crank); the default normalised blend never does.
TEST(DiepstratenBlend, WeightsNeverSumAboveOneByDefault) {
  float brightest = 0.0f;
  for (const auto& p : greyCrank("normalized").pixels) brightest = std::max({brightest, p.r, p.g, p.b});
  EXPECT_LE(brightest, 0.5f + 1e-3f);
  float additive = 0.0f;
  for (const auto& p : greyCrank("additive").pixels) additive = std::max(additive, p.r);
  EXPECT_GT(additive, 0.6f);  // the literal reading washes out
}

// An opaque shaft inside a transparent cylinder, seen from the front: its two long silhouette
// lines are drawn unbroken (every column along the shaft has its line pixels), though the
// surface right next to a silhouette is much nearer than the silhouette itself.
TEST(DiepstratenLines, SilhouettesInsideATransparentObjectAreUnbroken) {
  SceneObject glass{"glass", makeCappedCylinder({-2, 0, 0}, {2, 0, 0}, 1.0f, 48)};
  glass.roles = Role::Transparent;
  SceneObject shaft{"shaft", makeCappedCylinder({-1.5f, 0, 0}, {1.5f, 0, 0}, 0.2f, 32)};
  shaft.roles = Role::Opaque;
  Renderer renderer(sceneOf({glass, shaft}));
  RenderRequest r;
  r.width = r.height = 96;
  r.style = "view-dependent";
  r.settings = {{"boundaries", "implicit"}};
  const tlab::core::Image img = renderer.render(r);
  int columns = 0, broken = 0;
  for (int x = 30; x < 66; ++x) {  // the shaft spans about x = 22 … 74
    int line = 0;
    for (int y = 30; y < 66; ++y) line += (img.at(x, y).r + img.at(x, y).g + img.at(x, y).b) < 0.15f ? 1 : 0;
    ++columns;
    broken += line < 2 ? 1 : 0;
  }
  EXPECT_EQ(broken, 0) << "of " << columns << " columns";
}

// The renderer keeps the edge adjacency of its scene across frames (SceneCache): the silhouettes
// and Eq. 2's α still follow each frame's eye. One renderer drawing eyes A, B, A gives A's picture
// twice and, from B, the picture a renderer that never saw A draws; B's differs from A's.
TEST(ViewDependentAlpha, OneRendererRedoesTheSilhouettesForEveryEye) {
  const Scene scene = sceneOf({shell(1.0f, glm::vec3(0.3f, 0.0f, 0.0f)), opaqueBox(0.25f, glm::vec3(0.2f, 0.1f, 0))});
  const auto request = [&](glm::vec3 eye) {
    RenderRequest r;
    r.width = r.height = kSize;
    r.style = "view-dependent";
    Camera c = *scene.camera;
    c.eye = eye;
    r.camera = c;
    return r;
  };
  const glm::vec3 a(0, 0, 6), b(4.2f, 1.5f, 4.0f);
  Renderer renderer(scene);
  const tlab::core::Image first = renderer.render(request(a));
  const tlab::core::Image second = renderer.render(request(b));
  const tlab::core::Image third = renderer.render(request(a));
  Renderer fresh(scene);
  const tlab::core::Image freshB = fresh.render(request(b));
  EXPECT_TRUE(first.pixels == third.pixels);
  EXPECT_TRUE(second.pixels == freshB.pixels);
  EXPECT_FALSE(first.pixels == second.pixels);
}
