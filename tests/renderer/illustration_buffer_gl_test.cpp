// The illustration buffer against analytic layer counts, its overflow handling and determinism.
#include <gtest/gtest.h>

#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/frame/frame_context.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "tests/support/gl_fixture.hpp"
#include "tests/support/scoped_env.hpp"

using namespace tlab::render;

namespace {

RenderRequest request(int w, int h, FillMethod fill = FillMethod::CountScatter) {
  RenderRequest r;
  r.width = w;
  r.height = h;
  r.style = "constant";
  r.fill = fill;
  r.timePasses = false;
  return r;
}

std::uint16_t countAt(const Renderer& renderer, int w, int x, int y) { return renderer.layerCounts()[std::size_t(y) * w + x]; }

// Records of one quad (colour: depth, triangle, colour) and of two (with normal, ∇z and ids): the
// word-by-word and the quad paths of the fill and the sort.
std::vector<FragmentLayout> oneAndTwoQuadLayouts() {
  FragmentProperties colour, padded;
  colour |= FragmentProperty::Color;
  padded = colour;
  padded |= FragmentProperty::Normal;
  padded |= FragmentProperty::DepthGradient;
  padded |= FragmentProperty::Ids;
  return {FragmentLayout(colour), FragmentLayout(padded)};
}

// Looking down −z at the origin from 4 units away, for a 48×40 buffer.
RasterUniforms lookingDownZ() {
  RasterUniforms u;
  u.view = glm::lookAt(glm::vec3(0, 0, 4), glm::vec3(0), glm::vec3(0, 1, 0));
  u.projection = glm::perspective(0.9f, 48.0f / 40.0f, 0.1f, 20.0f);
  return u;
}

}  // namespace

class BothFillMethods : public ::testing::TestWithParam<FillMethod> {};

TEST_P(BothFillMethods, NestedSpheresGiveTwoLayersPerShellThroughTheCentre) {
  Renderer renderer(loadScene("builtin:nested-spheres?n=3"));
  renderer.render(request(65, 65, GetParam()));
  EXPECT_EQ(countAt(renderer, 65, 32, 32), 6);
  EXPECT_EQ(countAt(renderer, 65, 0, 0), 0);
  EXPECT_EQ(countAt(renderer, 65, 64, 64), 0);
}

TEST_P(BothFillMethods, CubeGivesTwoLayersInsideItsSilhouette) {
  Renderer renderer(loadScene("builtin:cube"));
  renderer.render(request(64, 64, GetParam()));
  EXPECT_EQ(countAt(renderer, 64, 32, 32), 2);
  EXPECT_EQ(countAt(renderer, 64, 0, 0), 0);
}

TEST_P(BothFillMethods, QuadStackGivesNLayersEverywhere) {
  Renderer renderer(loadScene("builtin:quad-stack?n=32&m=4"));
  RenderStats stats;
  renderer.render(request(48, 40, GetParam()), &stats);
  for (auto c : renderer.layerCounts()) ASSERT_EQ(c, 32);
  EXPECT_EQ(stats.fragments, 32u * 48u * 40u);
  EXPECT_EQ(stats.maxListLength, 32u);
  EXPECT_DOUBLE_EQ(stats.meanListLength, 32.0);
}

TEST_P(BothFillMethods, ListsAreSortedFrontToBackWithFacingAndIds) {
  Renderer renderer(loadScene("builtin:nested-spheres?n=3"));
  RenderRequest r = request(65, 65, GetParam());
  r.allProperties = true;
  renderer.render(r);
  const auto list = renderer.fragmentsAt(32, 32);
  ASSERT_EQ(list.size(), 6u);
  const std::uint32_t objects[6] = {0, 1, 2, 2, 1, 0};  // outer shell is object 0
  for (std::size_t i = 0; i < 6; ++i) {
    if (i > 0) {
      EXPECT_LT(list[i - 1].depth, list[i].depth);
    }
    EXPECT_EQ(list[i].object, objects[i]);
    EXPECT_EQ(list[i].frontFacing, i < 3);
    EXPECT_NEAR(glm::length(list[i].normal), 1.0f, 1e-3f);
  }
  // Each shell is its own connected component.
  EXPECT_NE(list[0].component, list[1].component);
  EXPECT_EQ(list[0].component, list[5].component);
}

// 20 layers: the count-scatter fill's first frame outgrows its 8 slots and scatters into the pool
// (a frame whose lists fit the slots needs no pool: AFrameInSlotsLeavesTheHeadsToWhoeverNeedsThem).
TEST_P(BothFillMethods, ForcedOverflowGivesTheSameImage) {
  const Scene scene = loadScene("builtin:quad-stack?n=20&m=4");
  Renderer large(scene), tiny(scene);
  RenderRequest big = request(96, 80, GetParam());
  big.initialPoolFragments = 1u << 20;
  RenderRequest small = big;
  small.initialPoolFragments = 16;
  RenderStats bigStats, smallStats;
  const tlab::core::Image a = large.render(big, &bigStats);
  const tlab::core::Image b = tiny.render(small, &smallStats);
  EXPECT_EQ(tlab::core::encodePng(a), tlab::core::encodePng(b));
  EXPECT_EQ(bigStats.rerenders, 0);
  EXPECT_EQ(bigStats.poolGrowths, 0);
  EXPECT_GE(smallStats.poolGrowths, 1);
  if (GetParam() == FillMethod::LinkedList) {
    EXPECT_GE(smallStats.rerenders, 1);
  }
  EXPECT_EQ(bigStats.fragments, smallStats.fragments);
}

INSTANTIATE_TEST_SUITE_P(Fill, BothFillMethods, ::testing::Values(FillMethod::CountScatter, FillMethod::LinkedList),
                         [](const auto& info) { return fillMethodName(info.param); });

TEST(IllustrationBuffer, BothFillMethodsGiveIdenticalImages) {
  Renderer renderer(loadScene("builtin:open-cylinders"));
  const tlab::core::Image a = renderer.render(request(96, 96, FillMethod::CountScatter));
  const tlab::core::Image b = renderer.render(request(96, 96, FillMethod::LinkedList));
  EXPECT_EQ(tlab::core::encodePng(a), tlab::core::encodePng(b));
}

TEST(IllustrationBuffer, RepeatedRendersAreByteIdentical) {
  Renderer renderer(loadScene("builtin:torus?major_segments=48&minor_segments=24"));
  const auto a = tlab::core::encodePng(renderer.render(request(80, 64)));
  const auto b = tlab::core::encodePng(renderer.render(request(80, 64)));
  Renderer fresh(loadScene("builtin:torus?major_segments=48&minor_segments=24"));
  const auto c = tlab::core::encodePng(fresh.render(request(80, 64)));
  EXPECT_EQ(a, b);
  EXPECT_EQ(a, c);
}

TEST(IllustrationBuffer, StylesAllocateOnlyWhatTheyNeed) {
  Renderer renderer(loadScene("builtin:sphere"));
  RenderStats stats;
  renderer.render(request(32, 32), &stats);
  EXPECT_EQ(stats.fragmentProperties, (std::vector<std::string>{"depth", "triangle", "color"}));
  RenderRequest opaque = request(32, 32);
  opaque.style = "opaque";
  renderer.render(opaque, &stats);
  EXPECT_EQ(stats.fragments, 0u);
  EXPECT_TRUE(stats.fragmentProperties.empty());
  EXPECT_THROW(renderer.layerCounts(), std::logic_error);  // no lists were built
}

TEST(IllustrationBuffer, ExceedingTheMemoryLimitSaysHowMuchWasNeeded) {
  tlab::gpu::ShaderCache shaders;
  FragmentBuffer buffer(shaders, 64, 64, FragmentLayout({}), FillMethod::CountScatter, 0, 40000);
  const Scene scene = loadScene("builtin:quad-stack?n=8");
  GpuScene gpu(scene);
  RasterUniforms u;
  u.view = scene.camera->view();
  u.projection = scene.camera->projection(1.0f);
  PassTimer timer(false);
  try {
    buffer.build(gpu, u, timer);
    FAIL();
  } catch (const std::exception& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("needs 32768 fragments"), std::string::npos) << msg;
    EXPECT_NE(msg.find("lower resolution"), std::string::npos) << msg;
  }
}

// Regression: at 2048x2048 a 1-D dispatch of 64-wide groups needs 65536 groups, one more than GL
// allows; compute passes now dispatch a 2-D grid.
TEST(IllustrationBuffer, RendersAt2048x2048) {
  Renderer renderer(loadScene("builtin:quad-stack?n=1"));
  RenderStats stats;
  const tlab::core::Image img = renderer.render(request(2048, 2048), &stats);
  EXPECT_EQ(stats.fragments, 2048u * 2048u);
  EXPECT_NE(img.at(2047, 2047), glm::vec4(0.0f));
  for (auto c : renderer.layerCounts()) ASSERT_EQ(c, 1);
}

// Issue #29: the count pass stores each pixel's first K records in per-pixel slots (one
// rasterization) when the largest list seen so far fits; a frame whose lists outgrow the slots
// falls back to the scatter pass. Both give the same sorted buffer, so the same pictures.
TEST(IllustrationBuffer, SlotFillAndItsScatterFallbackGiveTheSameSortedBuffer) {
  tlab::gpu::ShaderCache shaders;
  FragmentProperties colour;
  colour |= FragmentProperty::Color;
  FragmentBuffer buffer(shaders, 48, 40, FragmentLayout(colour), FillMethod::CountScatter);
  const Scene scene = loadScene("builtin:quad-stack?n=20&m=4");  // 20 layers: more than the first frame's 8 slots
  GpuScene gpu(scene);
  RasterUniforms u;
  u.view = scene.camera->view();
  u.projection = scene.camera->projection(48.0f / 40.0f);
  PassTimer timer(false);
  buffer.build(gpu, u, timer);
  EXPECT_EQ(buffer.slotsUsed(), 0u) << "20 layers overflow 8 slots: this frame scatters";
  ASSERT_EQ(buffer.fragmentCount(), 20u * 48u * 40u);
  const auto scattered = buffer.sortedRecords(0, buffer.fragmentCount());
  const auto heads = buffer.pixelHeads();
  buffer.build(gpu, u, timer);
  EXPECT_EQ(buffer.slotsUsed(), 20u) << "the next frame has a slot for every layer";
  EXPECT_EQ(buffer.fragmentCount(), 20u * 48u * 40u);
  EXPECT_EQ(buffer.pixelHeads(), heads);
  EXPECT_EQ(buffer.sortedRecords(0, buffer.fragmentCount()), scattered);
}

// Issue #29: records of 4 words or more are padded to quads of words, written by the fill and
// copied by the sort as uvec4s; shorter ones word by word. The two paths give the same words: a
// padded record (smart's 7 words with the ids, padded to 8) and `constant`'s 3-word record of the
// same scene hold the same depth, triangle and colour, record by record; the second quad arrives
// too (the ids differ between the stack's quads) and the padding is 0 — through the scatter pass
// (first frame: 20 layers overflow 8 slots), the slots (second frame) and the linked lists.
TEST(IllustrationBuffer, RecordsPaddedToQuadsHoldTheWordsOfTheWordByWordPath) {
  tlab::gpu::ShaderCache shaders;
  FragmentProperties colour, padded;
  colour |= FragmentProperty::Color;
  padded |= FragmentProperty::Color;
  padded |= FragmentProperty::Normal;
  padded |= FragmentProperty::DepthGradient;
  padded |= FragmentProperty::Ids;
  const FragmentLayout wordLayout(colour), quadLayout(padded);
  ASSERT_EQ(wordLayout.quads, 0u);
  ASSERT_EQ(quadLayout.stride, 8u);
  ASSERT_EQ(quadLayout.idsOffset, 6u);
  const Scene scene = loadScene("builtin:quad-stack?n=20&m=4");
  GpuScene gpu(scene);
  RasterUniforms u;
  u.view = scene.camera->view();
  u.projection = scene.camera->projection(48.0f / 40.0f);
  PassTimer timer(false);
  for (const FillMethod method : {FillMethod::CountScatter, FillMethod::LinkedList}) {
    FragmentBuffer words(shaders, 48, 40, wordLayout, method), quads(shaders, 48, 40, quadLayout, method);
    for (int frame = 0; frame < 2; ++frame) {
      words.build(gpu, u, timer);
      quads.build(gpu, u, timer);
      ASSERT_EQ(quads.fragmentCount(), 20u * 48u * 40u);
      ASSERT_EQ(words.fragmentCount(), quads.fragmentCount());
      const auto a = words.sortedRecords(0, words.fragmentCount());
      const auto b = quads.sortedRecords(0, quads.fragmentCount());
      std::size_t mismatches = 0, nonzeroPadding = 0;
      std::set<std::uint32_t> ids;
      for (std::size_t f = 0; f < quads.fragmentCount(); ++f) {
        for (std::size_t w = 0; w < 3; ++w) mismatches += a[f * 3 + w] != b[f * 8 + w];
        ids.insert(b[f * 8 + 6]);
        nonzeroPadding += b[f * 8 + 7] != 0;
      }
      EXPECT_EQ(mismatches, 0u) << fillMethodName(method) << ", frame " << frame;
      EXPECT_GE(ids.size(), 4u) << fillMethodName(method) << ", frame " << frame;
      EXPECT_EQ(nonzeroPadding, 0u) << fillMethodName(method) << ", frame " << frame;
    }
    if (method == FillMethod::CountScatter) {
      EXPECT_EQ(quads.slotsUsed(), 20u) << "the second frame fills the slots";
    }
  }
}

TEST(IllustrationBuffer, FramesFilledThroughSlotsAndThroughTheScatterPassAreByteIdentical) {
  Renderer renderer(loadScene("builtin:open-cylinders"));
  const auto first = tlab::core::encodePng(renderer.render(request(96, 80)));   // 8 slots: scatters if a list is longer
  const auto second = tlab::core::encodePng(renderer.render(request(96, 80)));  // slots sized to the longest list
  EXPECT_EQ(first, second);
}

// Issue #29: `constant` leaves the sort to its compose pass, which sorts each list as it blends
// (in registers up to 4 fragments; beyond, by the register network of 16 in frames whose slots
// hold lists longer than 8, else in the order buffer). Its pictures must equal, float for float,
// those of the linked-list fill, whose lists the sort pass sorts before the compose pass blends
// them: for lists of 1 to 20 fragments (2 to 12 of varied length in the nested spheres: both
// register paths in one frame; 16 in the stack of 16: the network full), from the slots (second
// frame) and from the scatter pass (a first frame whose lists outgrow the 8 slots it starts with).
// With the host passes on (the default where the GL runs on the CPU), the colours come sorted by
// host code instead and are blended by host code (the twenty-eighth round): the same pictures
// again, float for float.
TEST(IllustrationBuffer, ConstantSortingInItsComposePassEqualsTheSortPass) {
  for (const char* source : {"builtin:quad-stack?n=20&m=4", "builtin:quad-stack?n=16&m=3", "builtin:quad-stack?n=5&m=3",
                             "builtin:open-cylinders",
                             "builtin:nested-spheres?n=6", "builtin:torus"}) {
    SCOPED_TRACE(source);
    Renderer sortPass(loadScene(source));
    const tlab::core::Image expected = sortPass.render(request(72, 60, FillMethod::LinkedList));
    for (const char* hostPasses : {"off", "on"}) {
      SCOPED_TRACE(std::string("TLAB_HOST_PASSES=") + hostPasses);
      const tlab::testing::ScopedEnv passes("TLAB_HOST_PASSES", hostPasses);
      Renderer fused(loadScene(source));
      for (int frame = 0; frame < 2; ++frame) {
        const tlab::core::Image image = fused.render(request(72, 60));
        ASSERT_EQ(image.pixels.size(), expected.pixels.size());
        for (std::size_t i = 0; i < image.pixels.size(); ++i) ASSERT_EQ(image.pixels[i], expected.pixels[i]) << "pixel " << i << ", frame " << frame;
      }
    }
  }
}

// Issue #29, twenty-eighth round: for a compositor that sorts, with the sort as host code, the
// build writes the colour plane alone: each list's colour words in the order the sort pass would
// put the records in (a fill that sorts in its own pass is the reference), from the scatter pass
// (the first frame's 20-layer lists outgrow 8 slots) and from the slots, for records of one quad
// and of more; no sorted records (sorted() stays false, and a reader that wants them gets them
// sorted then). With the sort as a shader the compositor sorts, and no plane is written.
TEST(IllustrationBuffer, ACompositorThatSortsGetsTheColourPlaneSortedByHostCode) {
  tlab::gpu::ShaderCache shaders;
  PassTimer timer(false);
  for (const char* source : {"builtin:quad-stack?n=20&m=4", "builtin:nested-spheres?n=3"}) {
    const Scene scene = loadScene(source);
    GpuScene gpu(scene);
    const RasterUniforms u = lookingDownZ();
    for (const FragmentLayout& layout : oneAndTwoQuadLayouts()) {
      FragmentBuffer reference(shaders, 48, 40, layout, FillMethod::CountScatter);
      reference.build(gpu, u, timer);
      const std::size_t n = reference.fragmentCount();
      ASSERT_GT(n, 48u * 40u / 2);
      std::vector<std::uint32_t> expected;
      const auto records = reference.sortedRecords(0, n);
      for (std::size_t f = 0; f < n; ++f) expected.push_back(records[f * layout.stride + layout.colorOffset]);
      ASSERT_GT(std::set<std::uint32_t>(expected.begin(), expected.end()).size(), 1u);

      FragmentBuffer buffer(shaders, 48, 40, layout, FillMethod::CountScatter);
      buffer.setSortInCompose(true);
      buffer.setSortOnHost(true);
      std::set<std::uint32_t> slotsSeen;
      for (int frame = 0; frame < 2; ++frame) {
        SCOPED_TRACE(std::string(source) + ", stride " + std::to_string(layout.stride) + ", frame " + std::to_string(frame));
        buffer.build(gpu, u, timer);
        slotsSeen.insert(buffer.slotsUsed());
        EXPECT_FALSE(buffer.sorted());
        ASSERT_NE(buffer.colorPlane(), nullptr);
        ASSERT_EQ(buffer.fragmentCount(), n);
        std::vector<std::uint32_t> plane(n);
        buffer.colorPlane()->download(plane.data(), n * 4);
        EXPECT_EQ(plane, expected);
        EXPECT_EQ(buffer.pixelHeads(), reference.pixelHeads());
      }
      EXPECT_GT(*slotsSeen.rbegin(), 0u) << "the second frame fills slots";
      if (std::string(source).find("n=20") != std::string::npos) {
        EXPECT_EQ(*slotsSeen.begin(), 0u) << "the first frame scatters";
      }
      EXPECT_EQ(buffer.sortedRecords(0, n), records) << "sorted when read";

      buffer.setSortOnHost(false);
      buffer.build(gpu, u, timer);
      EXPECT_EQ(buffer.colorPlane(), nullptr) << "the compose pass sorts";

      // Records in slots need no pool: colours sorted from the slots leave a pool of 16 alone, and
      // a reader that wants the sorted records gets a pool then.
      if (std::string(source).find("nested") != std::string::npos) {
        FragmentBuffer small(shaders, 48, 40, layout, FillMethod::CountScatter, 16);
        small.setSortInCompose(true);
        small.setSortOnHost(true);
        small.build(gpu, u, timer);
        ASSERT_GT(small.slotsUsed(), 0u) << "lists of up to 6 fit the first frame's 8 slots";
        EXPECT_EQ(small.capacity(), 16u);
        ASSERT_NE(small.colorPlane(), nullptr);
        EXPECT_EQ(small.fragmentCount(), n);
        EXPECT_EQ(small.sortedRecords(0, n), records);
        EXPECT_EQ(small.capacity(), n);
      }
    }
  }
}

// Issue #29: a frame whose lists all fit their slots, for a compositor that sorts, runs no prefix
// sum and uses no pool; the heads and the fragment count, summed on the host when read, equal the
// prefix sum's, which runs when a reader needs the sorted lists, and the sorted lists equal those
// of a fill that sorts in its own pass.
TEST(IllustrationBuffer, AFrameInSlotsLeavesTheHeadsToWhoeverNeedsThem) {
  tlab::gpu::ShaderCache shaders;
  FragmentProperties colour;
  colour |= FragmentProperty::Color;
  const Scene scene = loadScene("builtin:nested-spheres?n=3");  // lists of 0 to 6 fragments
  GpuScene gpu(scene);
  const Camera camera = fitCamera(scene.boundingSphere(), 48.0f / 40.0f);
  RasterUniforms u;
  u.view = camera.view();
  u.projection = camera.projection(48.0f / 40.0f);
  PassTimer timer(false);
  FragmentBuffer reference(shaders, 48, 40, FragmentLayout(colour), FillMethod::CountScatter);
  reference.build(gpu, u, timer);  // sorts in its own pass, so runs the prefix sum in the fill
  const std::uint64_t n = reference.fragmentCount();
  ASSERT_GT(n, 48u * 40u / 2);

  FragmentBuffer buffer(shaders, 48, 40, FragmentLayout(colour), FillMethod::CountScatter, 16);
  buffer.setSortInCompose(true);
  buffer.setSortOnHost(false);  // with the sort as host code the build sorts the colours (next test)
  buffer.build(gpu, u, timer);
  ASSERT_GT(buffer.slotsUsed(), 0u);
  EXPECT_FALSE(buffer.sorted());
  EXPECT_EQ(buffer.capacity(), 16u) << "the pool of 16 fragments was left alone";
  EXPECT_EQ(buffer.poolGrowths(), 0);
  EXPECT_EQ(buffer.pixelCounts(), reference.pixelCounts());
  EXPECT_EQ(buffer.pixelHeads(), reference.pixelHeads()) << "summed on the host";
  EXPECT_EQ(buffer.fragmentCount(), n) << "summed on the host";
  EXPECT_EQ(buffer.sortedRecords(0, n), reference.sortedRecords(0, n)) << "the prefix sum ran for the sort";
  EXPECT_EQ(buffer.capacity(), n);
  EXPECT_EQ(buffer.pixelHeads(), reference.pixelHeads()) << "the prefix sum's";
  EXPECT_EQ(buffer.fragmentCount(), n) << "the prefix sum's";
}

// The prefix sum lists the pixels that hold a fragment, in pixel order, for the passes that run
// for those only (issue #29: the sort, smart transparency's connect and compose passes): exactly
// the pixels with a count above 0, for the slot fill, the scatter fill and the linked lists, and
// none for a frame without fragments. Summed by host code (the default where the GL runs on the
// CPU) and by buffer/prefix_sum.comp: the same heads (each the sum of the counts before
// it), covered pixels, fragment count and sorted records.
TEST(IllustrationBuffer, ThePrefixSumListsThePixelsThatHoldAFragment) {
  tlab::gpu::ShaderCache shaders;
  FragmentProperties colour;
  colour |= FragmentProperty::Color;
  PassTimer timer(false);
  struct Case {
    const char* source;
    FillMethod method;
    bool slots;  // lists of up to 8 fit the first frame's slots; 12 make it scatter
  };
  bool singleFragments = false;  // some pixel holds exactly one fragment (an open surface)
  for (const Case& c : {Case{"builtin:nested-spheres?n=3", FillMethod::CountScatter, true},
                        Case{"builtin:nested-spheres?n=6", FillMethod::CountScatter, false},
                        Case{"builtin:nested-spheres?n=3", FillMethod::LinkedList, false},
                        Case{"builtin:open-cylinders", FillMethod::CountScatter, true}}) {
    const Scene scene = loadScene(c.source);
    GpuScene gpu(scene);
    const Camera camera = fitCamera(scene.boundingSphere(), 48.0f / 40.0f);
    RasterUniforms u;
    u.view = camera.view();
    u.projection = camera.projection(48.0f / 40.0f);
    std::vector<std::uint32_t> recordsOnHost;
    for (const bool onHost : {true, false}) {
      SCOPED_TRACE(std::string(c.source) + " " + fillMethodName(c.method) + (onHost ? ", host code" : ", shader"));
      FragmentBuffer buffer(shaders, 48, 40, FragmentLayout(colour), c.method);
      buffer.setPrefixSumOnHost(onHost);
      buffer.build(gpu, u, timer);
      EXPECT_EQ(buffer.slotsUsed() > 0, c.slots);
      std::vector<std::uint32_t> expected, heads;
      const auto counts = buffer.pixelCounts();
      std::uint32_t sum = 0;
      for (std::uint32_t p = 0; p < counts.size(); ++p) {
        heads.push_back(sum);
        sum += counts[p];
        if (counts[p] > 0) expected.push_back(p);
        singleFragments = singleFragments || counts[p] == 1;
      }
      ASSERT_GT(expected.size(), 200u);
      ASSERT_LT(expected.size(), counts.size()) << "the spheres leave background around them";
      EXPECT_EQ(buffer.coveredPixelCount(), expected.size());
      EXPECT_EQ(buffer.coveredPixels(), expected);
      EXPECT_EQ(buffer.pixelHeads(), heads);
      EXPECT_EQ(buffer.fragmentCount(), sum);
      const auto records = buffer.sortedRecords(0, sum);
      if (onHost) recordsOnHost = records;
      else EXPECT_EQ(records, recordsOnHost);
      if (c.method == FillMethod::LinkedList) {
        RasterUniforms away = u;
        away.view = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 100.0f)) * u.view;  // the scene behind the eye
        buffer.build(gpu, away, timer);
        EXPECT_EQ(buffer.fragmentCount(), 0u);
        EXPECT_EQ(buffer.coveredPixelCount(), 0u);
        EXPECT_TRUE(buffer.coveredPixels().empty());
      }
    }
  }
  EXPECT_TRUE(singleFragments);
}

// A pass that asks for the sorted lists of a frame whose sort was left to the compose pass gets
// them sorted then (here `tlab inspect`'s read-back after a `constant` frame).
TEST(IllustrationBuffer, SortedListsOfAFrameLeftUnsortedAreSortedWhenRead) {
  Renderer renderer(loadScene("builtin:quad-stack?n=12&m=2"));
  renderer.render(request(40, 40));
  const auto list = renderer.fragmentsAt(20, 20);
  ASSERT_EQ(list.size(), 12u);
  for (std::size_t i = 1; i < list.size(); ++i) EXPECT_LT(list[i - 1].depth, list[i].depth);
  EXPECT_NE(list.front().color, glm::vec4(0.0f)) << "the records carry their colour";
}

namespace {

// The cube (edge 1 at the origin) in three views: small in the lower left of the picture, all
// around a camera inside it, and out of the picture to the left.
struct CubeView {
  const char* name;
  Camera camera;
};
std::vector<CubeView> cubeViews() {
  Camera aside, inside, away;
  aside.eye = {0.0f, 0.0f, 6.0f};
  aside.target = {1.6f, 1.3f, 0.0f};
  inside.eye = {0.1f, 0.2f, 0.1f};
  inside.target = {0.0f, 0.0f, -1.0f};
  away.eye = {0.0f, 0.0f, 6.0f};
  away.target = {6.0f, 0.0f, 0.0f};
  return {{"aside", aside}, {"inside", inside}, {"away", away}};
}

}  // namespace

// Issue #29: constant's compose pass runs on the scene's footprint only. It holds every pixel
// with a fragment; it is a small part of the picture when the scene is, the whole picture when
// the camera stands inside the scene's box, and empty when the scene is out of the picture.
TEST(IllustrationBuffer, TheSceneFootprintHoldsEveryFragment) {
  const Scene scene = loadScene("builtin:cube");
  GpuScene gpu(scene);
  tlab::gpu::ShaderCache shaders;
  FragmentProperties colour;
  colour |= FragmentProperty::Color;
  const int w = 96, h = 80;
  FragmentBuffer buffer(shaders, w, h, FragmentLayout(colour), FillMethod::CountScatter);
  const StyleParams params;
  tlab::core::Image image(w, h);
  PassTimer timer(false);
  for (const auto& [name, camera] : cubeViews()) {
    SCOPED_TRACE(name);
    RasterUniforms u;
    u.view = camera.view();
    u.projection = camera.projection(float(w) / float(h));
    FrameContext frame{scene, gpu, u, camera, params, w, h, scene.background, &buffer, image, shaders};
    const PixelRect r = sceneFootprint(frame);
    buffer.build(gpu, u, timer);
    const auto counts = buffer.pixelCounts();  // row 0 = bottom, as the footprint's
    std::size_t covered = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (counts[std::size_t(y) * w + x] > 0) {
          ++covered;
          ASSERT_TRUE(x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1) << "pixel " << x << "," << y << " outside the footprint";
        }
    if (std::string(name) == "aside") {
      EXPECT_GT(covered, 20u);
      EXPECT_LT(r.pixels(), std::size_t(w) * h / 8) << "a small footprint";
      EXPECT_GT(r.x0, 0);
      EXPECT_GT(r.y0, 0);
    } else if (std::string(name) == "inside") {
      EXPECT_EQ(covered, std::size_t(w) * h);
      EXPECT_EQ(r.pixels(), std::size_t(w) * h) << "the whole picture";
    } else {
      EXPECT_EQ(covered, 0u);
      EXPECT_EQ(r.pixels(), 0u) << "nothing to compose";
    }
  }
}

// ... and every pixel of constant's picture with a fragment is composed (not the background),
// every other is exactly the background (opaque), for the slot fill and the scatter pass.
TEST(IllustrationBuffer, ConstantComposesEveryCoveredPixelAndPaintsTheRestBackground) {
  const Scene scene = loadScene("builtin:cube");
  const glm::vec4 background(glm::vec3(scene.background), 1.0f);
  for (const auto& [name, camera] : cubeViews()) {
    for (FillMethod fill : {FillMethod::CountScatter, FillMethod::LinkedList}) {
      SCOPED_TRACE(std::string(name) + " " + fillMethodName(fill));
      Renderer renderer(scene);
      RenderRequest r = request(96, 80, fill);
      r.camera = camera;
      const tlab::core::Image image = renderer.render(r);
      const auto counts = renderer.layerCounts();  // row 0 = top, as the image's
      ASSERT_EQ(counts.size(), image.pixels.size());
      for (std::size_t i = 0; i < counts.size(); ++i) {
        if (counts[i] == 0) {
          ASSERT_EQ(image.pixels[i], background) << "pixel " << i;
        } else {
          ASSERT_NE(image.pixels[i], background) << "pixel " << i;
        }
      }
    }
  }
}

// Issue #29: with the colour plane on, the sort also writes each fragment's colour word alone, in
// the sorted order — the colour word of the sorted record at the same index — wherever the
// unsorted records sit (the scatter pass's block, the slots, at most 8 slots, the linked lists)
// and whether records are copied word by word or in quads. Off, no plane is written.
TEST(IllustrationBuffer, TheColorPlaneHoldsEachSortedRecordsColour) {
  tlab::gpu::ShaderCache shaders;
  PassTimer timer(false);
  // 20 layers (the first frame scatters, the second fills 20 slots) and at most 4 (8 slots or fewer).
  for (const char* source : {"builtin:quad-stack?n=20&m=4", "builtin:nested-spheres?n=2"}) {
    const Scene scene = loadScene(source);
    GpuScene gpu(scene);
    const RasterUniforms u = lookingDownZ();
    for (const FragmentLayout& layout : oneAndTwoQuadLayouts())
      for (const FillMethod method : {FillMethod::CountScatter, FillMethod::LinkedList}) {
        FragmentBuffer buffer(shaders, 48, 40, layout, method);
        buffer.build(gpu, u, timer);
        EXPECT_EQ(buffer.colorPlane(), nullptr);
        buffer.setColorPlane(true);
        std::set<std::uint32_t> slotsSeen;
        for (int frame = 0; frame < 2; ++frame) {
          SCOPED_TRACE(std::string(source) + ", stride " + std::to_string(layout.stride) + ", " + fillMethodName(method) +
                       ", frame " + std::to_string(frame));
          buffer.build(gpu, u, timer);
          slotsSeen.insert(buffer.slotsUsed());
          const std::size_t n = buffer.fragmentCount();
          ASSERT_GT(n, 0u);
          ASSERT_NE(buffer.colorPlane(), nullptr);
          std::vector<std::uint32_t> plane(n);
          buffer.colorPlane()->download(plane.data(), n * 4);
          const auto records = buffer.sortedRecords(0, n);
          std::size_t mismatches = 0;
          std::set<std::uint32_t> colours;
          for (std::size_t f = 0; f < n; ++f) {
            mismatches += plane[f] != records[f * layout.stride + layout.colorOffset];
            colours.insert(plane[f]);
          }
          EXPECT_EQ(mismatches, 0u);
          EXPECT_GT(colours.size(), 1u);  // the scenes' layers have colours of their own
        }
        if (method == FillMethod::CountScatter) { EXPECT_GT(*slotsSeen.rbegin(), 0u) << "the second frame fills slots"; }
      }
  }
}
