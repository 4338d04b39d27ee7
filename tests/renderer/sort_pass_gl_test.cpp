// The sort pass (buffer/sort.comp, issue #29): lists up to 16 long sorted in registers by a
// merge network give the very sorted buffer of the insertion sort in the order buffer, on lists
// of every length from 1 to 20 (the network's padding from 15 keys to none; the order buffer past
// 16) with ties in depth between near and far positions of a list, from the slots and from the
// scatter pass. The sort as host code (buffer/host_sort.hpp, the default where the GL runs on the
// CPU) writes the same words: records, colour plane and list steps.
#include <gtest/gtest.h>

#include <set>

#include "renderer/scene/scene_source.hpp"
#include "tests/renderer/smart_rig.hpp"
#include "tests/support/gl_fixture.hpp"

using namespace tlab::render;

namespace {

// 20 centred squares, square i of half-size 1 - i / 20, so a pixel inside square i but not
// i + 1 lists i + 1 fragments: every length from 1 to 20 (the depths differ by at most 0.09 at
// distance 3, too little to change which square looks larger). Square i lies at depth step
// (7 i) mod `period`: with period 10 each depth is used twice, by squares 10 apart (ties only in
// lists over 10); with period 3 by every third square (ties in lists of 4 and more); ties are
// broken by triangle. The squares alternate between two objects, and they are drawn in
// an order that is not the depth order.
Scene nestedSquares(int period = 10, int squares = 20) {
  Scene s;
  s.name = "nested-squares-" + std::to_string(period) + "-" + std::to_string(squares);
  for (int object = 0; object < 2; ++object) {
    SceneObject o;
    o.name = "squares-" + std::to_string(object);
    s.objects.push_back(o);
  }
  for (int i = 0; i < squares; ++i) {
    const float h = 1.0f - float(i) / 20.0f, z = float((i * 7) % period) * 0.01f - 0.05f;
    appendMesh(s.objects[std::size_t(i % 2)].mesh, makeQuad({0, 0, z}, {h, 0, 0}, {0, h, 0}));
  }
  s.camera = Camera{};
  s.camera->eye = {0, 0, 3};
  s.camera->nearPlane = 1;
  s.camera->farPlane = 10;
  return s;
}

enum class Sorter { Registers, OrderBuffer, HostCode };

// What a build's sort wrote: the records, and for the covered pixels the colour plane and each
// list's steps (the floats' bits).
struct Sorted {
  std::vector<std::uint32_t> records, colors, steps;
  bool operator==(const Sorted&) const = default;
};

// Two builds (the first may overflow the 8 starting slots and scatter; the second fills slots)
// of the same buffer, sorted by the shader in registers or only in the order buffer, or by host
// code: what each sort wrote.
std::vector<Sorted> sortedBuilds(const Scene& scene, int size, Sorter sorter, std::vector<std::uint32_t>& slots,
                                 std::vector<std::uint32_t>& counts) {
  GpuScene gpu(scene);
  tlab::gpu::ShaderCache shaders;
  const SmartStyle style;
  const StyleParams params = style.resolve({});
  FragmentBuffer buffer(shaders, size, size, FragmentLayout(style.properties(params, {gpu.componentCount()})),
                        FillMethod::CountScatter);
  buffer.setRegisterSort(sorter == Sorter::Registers);
  buffer.setSortOnHost(sorter == Sorter::HostCode);
  buffer.setColorPlane(true);
  const Camera camera = scene.camera ? *scene.camera : fitCamera(scene.boundingSphere(), 1.0f);
  RasterUniforms u;
  u.view = camera.view();
  u.projection = camera.projection(1.0f);
  PassTimer timer(false);
  std::vector<Sorted> out;
  for (int frame = 0; frame < 2; ++frame) {
    buffer.build(gpu, u, timer);
    slots.push_back(buffer.slotsUsed());
    Sorted sorted;
    const std::size_t n = buffer.fragmentCount();
    sorted.records = buffer.sortedRecords(0, n);
    std::vector<std::uint32_t> colors(n), steps(buffer.pixels() * 2);
    EXPECT_TRUE(buffer.colorPlane() && buffer.listSteps());
    buffer.colorPlane()->download(colors.data(), n * 4);
    buffer.listSteps()->download(steps.data(), steps.size() * 4);
    counts = buffer.pixelCounts();
    for (std::size_t p = 0; p < counts.size(); ++p)  // (the steps of an empty pixel are left as they were)
      if (counts[p] > 0) sorted.steps.insert(sorted.steps.end(), {steps[2 * p], steps[2 * p + 1]});
    sorted.colors = colors;
    out.push_back(sorted);
  }
  return out;
}

}  // namespace

TEST(SortPass, RegisterSortAndHostCodeEqualInsertionSortOnEveryListLength) {
  for (const auto& [scene, size] : {std::pair{nestedSquares(), 96}, std::pair{nestedSquares(3), 96},
                                    std::pair{nestedSquares(3, 8), 96}, std::pair{loadScene("builtin:torus"), 64},
                                    std::pair{loadScene("builtin:quad-stack?n=16&m=3"), 24},
                                    std::pair{loadScene("builtin:quad-stack?n=40&m=3"), 24},  // past 32: host code's stable_sort
                                    std::pair{loadScene("builtin:nested-spheres?n=3"), 48}}) {
    std::vector<std::uint32_t> slotsA, slotsB, slotsC, counts, countsB, countsC;
    const auto registers = sortedBuilds(scene, size, Sorter::Registers, slotsA, counts);
    const auto reference = sortedBuilds(scene, size, Sorter::OrderBuffer, slotsB, countsB);
    const auto host = sortedBuilds(scene, size, Sorter::HostCode, slotsC, countsC);
    EXPECT_EQ(slotsA, slotsB) << scene.name;
    EXPECT_EQ(slotsC, slotsB) << scene.name;
    for (std::size_t frame = 0; frame < 2; ++frame) {
      ASSERT_EQ(registers[frame].records.size(), reference[frame].records.size()) << scene.name;
      ASSERT_FALSE(reference[frame].steps.empty()) << scene.name;
      EXPECT_TRUE(registers[frame] == reference[frame]) << scene.name << " frame " << frame;
      EXPECT_TRUE(host[frame] == reference[frame]) << scene.name << " frame " << frame << ", host code";
    }
    if (scene.name == "nested-squares-3-8") {  // lists of 1..8 with ties, in 8 slots: the 8-register network
      const std::set<std::uint32_t> lengths(counts.begin(), counts.end());
      for (std::uint32_t n = 1; n <= 8; ++n) EXPECT_TRUE(lengths.count(n)) << "no list of " << n;
      EXPECT_EQ(slotsA, (std::vector<std::uint32_t>{8u, 8u}));
    } else if (scene.name.rfind("nested-squares", 0) == 0) {  // every length 1..20 occurs, and both fill paths ran
      const std::set<std::uint32_t> lengths(counts.begin(), counts.end());
      for (std::uint32_t n = 1; n <= 20; ++n) EXPECT_TRUE(lengths.count(n)) << "no list of " << n;
      EXPECT_EQ(slotsA, (std::vector<std::uint32_t>{0u, 20u}));
    }
  }
}

// The sorted lists are in (depth, triangle) order, each a permutation of its pixel's fragments:
// checked on the host, independently of either sort; the scenes tie in depth in lists of up to 8
// and of 9 to 16 (the halves of the network).
TEST(SortPass, RegisterSortedListsAreInDepthThenTriangleOrder) {
  for (const auto& [period, sorter] : {std::pair{10, Sorter::Registers}, std::pair{3, Sorter::Registers},
                                       std::pair{10, Sorter::HostCode}, std::pair{3, Sorter::HostCode}}) {
    std::vector<std::uint32_t> slots, counts;
    const auto builds = sortedBuilds(nestedSquares(period), 96, sorter, slots, counts);
    GpuScene gpu(nestedSquares(period));
    const SmartStyle style;
    const std::uint32_t stride = FragmentLayout(style.properties(style.resolve({}), {gpu.componentCount()})).stride;
    for (const auto& build : builds) {
      const auto& records = build.records;
      std::size_t head = 0, tiesUpTo8 = 0, ties9To16 = 0;
      for (std::uint32_t n : counts) {
        for (std::uint32_t i = 1; i < n; ++i) {
          const std::uint32_t* a = &records[(head + i - 1) * stride];
          const std::uint32_t* b = &records[(head + i) * stride];
          ASSERT_TRUE(a[0] < b[0] || (a[0] == b[0] && a[1] < b[1])) << "list at " << head << ", layer " << i;
          (n <= 8 ? tiesUpTo8 : ties9To16) += n <= 16 && a[0] == b[0];
        }
        head += n;
      }
      EXPECT_EQ(head, records.size() / stride);
      EXPECT_GT(ties9To16, 0u) << "period " << period;
      if (period == 3) {
        EXPECT_GT(tiesUpTo8, 0u);
      }
    }
  }
}
