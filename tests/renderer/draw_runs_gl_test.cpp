// A scene drawn in runs (GpuScene::draw; issue #29, twenty-seventh round): where the GL runs on
// the CPU, llvmpipe bins one run while it rasterizes the last. Every record, picture and count is
// that of one draw call.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "renderer/buffer/fragment_buffer.hpp"
#include "renderer/frame/frame_context.hpp"
#include "renderer/frame/gpu_scene.hpp"
#include "renderer/gpu/gl_error.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "tests/support/gl_fixture.hpp"
#include "tests/support/scoped_env.hpp"

using namespace tlab::render;
using tlab::testing::ScopedEnv;

TEST(DrawRuns, ByDefaultOnePerTwelveAndAHalfThousandTrianglesWhereTheGlIsTheCpu) {
  EXPECT_EQ(defaultDrawRuns(100000, false), 1u);  // a GPU's driver pipelines one call itself
  EXPECT_EQ(defaultDrawRuns(100000, true), kMaxDrawRuns);
  EXPECT_EQ(defaultDrawRuns(kTrianglesPerDrawRun - 1, true), 1u);
  EXPECT_EQ(defaultDrawRuns(3 * kTrianglesPerDrawRun, true), 3u);
  EXPECT_EQ(defaultDrawRuns(0, true), 1u);
}

// TLAB_DRAW_RUNS overrides the default; another value than auto or 1-64 is one line.
TEST(DrawRuns, TheSettingPicksTheRunsOrIsRefusedInOneLine) {
  const Scene scene = loadScene("builtin:torus?triangles=30000");
  {
    const ScopedEnv unset("TLAB_DRAW_RUNS", nullptr);
    EXPECT_EQ(GpuScene(scene).drawRuns(), defaultDrawRuns(GpuScene(scene).triangleCount(), tlab::gpu::glRunsOnCpu()));
  }
  {
    const ScopedEnv five("TLAB_DRAW_RUNS", "5");
    EXPECT_EQ(GpuScene(scene).drawRuns(), 5u);
  }
  {
    const ScopedEnv one("TLAB_DRAW_RUNS", "1");
    EXPECT_EQ(GpuScene(scene).drawRuns(), 1u);
  }
  for (const char* wrong : {"0", "65", "many", "4x", "-2", ""}) {
    const ScopedEnv set("TLAB_DRAW_RUNS", wrong);
    try {
      GpuScene g(scene);
      ADD_FAILURE() << "TLAB_DRAW_RUNS='" << wrong << "' was accepted";
    } catch (const tlab::gpu::GlError& e) {
      EXPECT_EQ(std::string(e.what()), std::string("TLAB_DRAW_RUNS must be auto or a whole number from 1 to 64, not '") + wrong + "'");
    }
  }
}

// Each run's gl_PrimitiveID is offset by its first triangle, and the GL rasterizes the runs in
// order: the counts, heads and sorted records (triangle ids included) are those of one call, for
// the slot fill, the scatter fill and linked lists; more runs than triangles are one a triangle.
TEST(DrawRuns, AFillDrawnInRunsStoresTheRecordsOfOneDrawCall) {
  tlab::gpu::ShaderCache shaders;
  FragmentProperties smart;
  for (FragmentProperty p : {FragmentProperty::Color, FragmentProperty::Normal, FragmentProperty::DepthGradient, FragmentProperty::Ids})
    smart |= p;
  PassTimer timer(false);
  struct Case {
    const char* source;
    FillMethod method;
    bool slots;
  };
  for (const Case& c : {Case{"builtin:torus?triangles=3000", FillMethod::CountScatter, true},
                        Case{"builtin:nested-spheres?n=6", FillMethod::CountScatter, false},
                        Case{"builtin:nested-spheres?n=3", FillMethod::LinkedList, false},
                        Case{"builtin:quad-stack?n=8", FillMethod::CountScatter, true}}) {
    const Scene scene = loadScene(c.source);
    GpuScene gpu(scene);
    const Camera camera = fitCamera(scene.boundingSphere(), 56.0f / 44.0f);
    RasterUniforms u;
    u.view = camera.view();
    u.projection = camera.projection(56.0f / 44.0f);
    std::vector<std::uint32_t> counts, heads, records;
    for (const std::size_t runs : {std::size_t(1), std::size_t(3), std::size_t(7), gpu.triangleCount() + 5}) {
      SCOPED_TRACE(std::string(c.source) + " " + fillMethodName(c.method) + ", " + std::to_string(runs) + " runs");
      gpu.setDrawRuns(runs);
      FragmentBuffer buffer(shaders, 56, 44, FragmentLayout(smart), c.method);
      buffer.build(gpu, u, timer);
      EXPECT_EQ(buffer.slotsUsed() > 0, c.slots);
      ASSERT_GT(buffer.fragmentCount(), 500u);
      if (runs == 1) {
        counts = buffer.pixelCounts();
        heads = buffer.pixelHeads();
        records = buffer.sortedRecords(0, buffer.fragmentCount());
        std::set<std::uint32_t> triangles;  // word 1 of a record: its triangle (OFF_PRIM)
        const FragmentLayout layout(smart);
        for (std::size_t f = 0; f < buffer.fragmentCount(); ++f) triangles.insert(records[f * layout.stride + 1]);
        EXPECT_GT(*triangles.rbegin(), gpu.triangleCount() / 2) << "ids of the later runs' triangles";
        continue;
      }
      EXPECT_EQ(buffer.pixelCounts(), counts);
      EXPECT_EQ(buffer.pixelHeads(), heads);
      EXPECT_EQ(buffer.sortedRecords(0, buffer.fragmentCount()), records);
    }
  }
}

// Every style, through every way of drawing the scene (the fills, the k-buffer of `dynamic` and
// `curvature`, the raster pass of `opaque` and of `unsorted`'s blending in arrival order, depth
// peeling), draws the same picture in runs as in one call, two frames each.
TEST(DrawRuns, EveryStyleDrawsTheSamePictureInRunsAsInOneCall) {
  struct Case {
    const char* style;
    bool peel;
  };
  for (const Case& c : {Case{"opaque", false}, Case{"unsorted", false}, Case{"constant", false}, Case{"smart", false},
                        Case{"angle", false}, Case{"normal-variation", false}, Case{"iris", false}, Case{"iris", true},
                        Case{"view-dependent", false}, Case{"dynamic", false}, Case{"curvature", false}}) {
    SCOPED_TRACE(std::string(c.style) + (c.peel ? " (depth peeling)" : ""));
    RenderRequest r;
    r.width = 64;
    r.height = 52;
    r.style = c.style;
    r.depthPeeling = c.peel;
    std::vector<tlab::core::Image> pictures[2];
    for (const char* runs : {"1", "6"}) {
      const ScopedEnv set("TLAB_DRAW_RUNS", runs);
      Renderer renderer(loadScene("builtin:torus?triangles=4000"));
      for (int frame = 0; frame < 2; ++frame) pictures[runs[0] == '1' ? 0 : 1].push_back(renderer.render(r));
    }
    for (int frame = 0; frame < 2; ++frame) EXPECT_TRUE(pictures[0][frame].pixels == pictures[1][frame].pixels) << "frame " << frame;
  }
}
