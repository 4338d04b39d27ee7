// The sort pass as host code (buffer/host_sort.hpp, issue #29), on hand-made lists whose sorted
// order is known: ties in depth broken by the triangle, then by where the record sat; pixels in
// slots and in blocks; lists read in the order that sorted the last one; the colour plane and the
// list steps; lists past the insertion sort's 32; and the same words from one thread and from
// several. (The GL suite compares it with the shader: tests/renderer/sort_pass_gl_test.cpp.)
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <vector>

#include "renderer/buffer/host_sort.hpp"

using namespace tlab::render;

namespace {

constexpr std::uint32_t kStride = 4;  // depth, triangle, colour, one more word (a gradient's x where asked)

std::uint32_t floatBits(float f) {
  std::uint32_t w;
  std::memcpy(&w, &f, 4);
  return w;
}

// Lists in blocks: pixel p's records from heads[p], as `lists` gives them (each record: depth bits,
// triangle, colour word; the fourth word is the colour again).
struct Blocks {
  std::vector<std::uint32_t> records, counts, heads, covered;
  explicit Blocks(const std::vector<std::vector<std::array<std::uint32_t, 3>>>& lists) {
    for (std::uint32_t p = 0; p < lists.size(); ++p) {
      heads.push_back(std::uint32_t(records.size() / kStride));
      counts.push_back(std::uint32_t(lists[p].size()));
      if (!lists[p].empty()) covered.push_back(p);
      for (const auto& r : lists[p]) records.insert(records.end(), {r[0], r[1], r[2], r[2]});
    }
  }
  UnsortedLists in() const { return {records.data(), kStride, 0, counts.data(), heads.data(), covered.data(), covered.size()}; }
};

// The colour words of the sorted records, in order.
std::vector<std::uint32_t> colorsOf(const std::vector<std::uint32_t>& sorted) {
  std::vector<std::uint32_t> c;
  for (std::size_t i = 2; i < sorted.size(); i += kStride) c.push_back(sorted[i]);
  return c;
}

}  // namespace

TEST(HostSort, TiesInDepthGoByTriangleThenByRecord) {
  const Blocks b({{{5, 2, 100}, {3, 9, 101}, {5, 1, 102}, {3, 9, 103}, {1, 0, 104}}, {}, {{7, 0, 200}}});
  std::vector<std::uint32_t> sorted(b.records.size(), 0xDEADu), plane(6, 0xDEADu);
  sortListsOnHost(b.in(), {sorted.data(), plane.data(), 2, nullptr, 0}, 1);
  EXPECT_EQ(colorsOf(sorted), (std::vector<std::uint32_t>{104, 101, 103, 102, 100, 200}));
  EXPECT_EQ(plane, (std::vector<std::uint32_t>{104, 101, 103, 102, 100, 200}));
  EXPECT_EQ(std::vector<std::uint32_t>(sorted.begin(), sorted.begin() + 8), (std::vector<std::uint32_t>{1, 0, 104, 104, 3, 9, 101, 101}))
      << "each record copied whole";
}

// A compositor that reads the colour plane alone gets the plane without the sorted records
// (null: none written), in the same order as with them.
TEST(HostSort, TheColourPlaneAloneIsSortedWithoutTheRecords) {
  const Blocks b({{{5, 2, 100}, {3, 9, 101}, {5, 1, 102}, {3, 9, 103}, {1, 0, 104}}, {}, {{7, 0, 200}}});
  std::vector<std::uint32_t> plane(6, 0xDEADu);
  sortListsOnHost(b.in(), {nullptr, plane.data(), 2, nullptr, 0}, 1);
  EXPECT_EQ(plane, (std::vector<std::uint32_t>{104, 101, 103, 102, 100, 200}));
}

TEST(HostSort, SlotsHoldThePixelsIthRecordAtIPixelsOn) {
  // 3 pixels, 2 slots: pixel 0 holds 2 fragments, pixel 1 none, pixel 2 one.
  const std::size_t pixels = 3;
  std::vector<std::uint32_t> records(2 * pixels * kStride, 0xBADu);
  const auto put = [&](std::size_t slot, std::size_t pixel, std::uint32_t depth, std::uint32_t colour) {
    const std::size_t at = (slot * pixels + pixel) * kStride;
    records[at] = depth;
    records[at + 1] = 0;
    records[at + 2] = records[at + 3] = colour;
  };
  put(0, 0, 9, 10);
  put(1, 0, 4, 11);
  put(0, 2, 6, 12);
  const std::vector<std::uint32_t> counts{2, 0, 1}, heads{0, 2, 2}, covered{0, 2};
  std::vector<std::uint32_t> sorted(3 * kStride);
  sortListsOnHost({records.data(), kStride, pixels, counts.data(), heads.data(), covered.data(), covered.size()},
                  {sorted.data(), nullptr, 0, nullptr, 0}, 1);
  EXPECT_EQ(colorsOf(sorted), (std::vector<std::uint32_t>{11, 10, 12}));
}

TEST(HostSort, TheLastListsOrderIsTriedFirstAndTiesStillGoByRecord) {
  // Each list of 3 is read in the order that sorted the last one: pixel 1's tie, read with its
  // second record first, still goes by record; pixel 3 is sorted as read in pixel 2's order.
  const Blocks b({{{2, 0, 100}, {1, 0, 101}, {2, 0, 102}},
                  {{5, 0, 200}, {5, 0, 201}, {3, 0, 202}},
                  {{9, 0, 300}, {8, 0, 301}, {7, 0, 302}},
                  {{6, 0, 400}, {5, 0, 401}, {4, 0, 402}},
                  {{1, 1, 500}, {1, 0, 501}}});
  std::vector<std::uint32_t> sorted(b.records.size());
  sortListsOnHost(b.in(), {sorted.data(), nullptr, 0, nullptr, 0}, 1);
  EXPECT_EQ(colorsOf(sorted), (std::vector<std::uint32_t>{101, 100, 102, 202, 200, 201, 302, 301, 300, 402, 401, 400, 501, 500}));
}

TEST(HostSort, ListStepsAreTheLargestGradientMagnitudes) {
  std::vector<std::uint32_t> records;
  const std::vector<std::pair<float, float>> gradients{{-0.5f, 0.25f}, {0.125f, -2.0f}, {0.0f, 1.0f}};
  for (std::uint32_t i = 0; i < gradients.size(); ++i)
    records.insert(records.end(), {i, 0, floatBits(gradients[i].first), floatBits(gradients[i].second)});
  const std::vector<std::uint32_t> counts{0, 3}, heads{0, 0}, covered{1};
  std::vector<std::uint32_t> sorted(records.size());
  std::vector<float> steps(4, -1.0f);
  sortListsOnHost({records.data(), kStride, 0, counts.data(), heads.data(), covered.data(), 1}, {sorted.data(), nullptr, 0, steps.data(), 2}, 1);
  EXPECT_EQ(steps, (std::vector<float>{-1.0f, -1.0f, 0.5f, 2.0f})) << "an empty pixel's steps are left as they were";
}

TEST(HostSort, ListsLongerThanTheInsertionSortStayStable) {
  // 40 records, record i at depth (39 - i) / 2: pairs tie, and each pair keeps its order.
  std::vector<std::array<std::uint32_t, 3>> list;
  for (std::uint32_t i = 0; i < 40; ++i) list.push_back({(39 - i) / 2, 7, i});
  const Blocks b({list});
  std::vector<std::uint32_t> sorted(b.records.size());
  sortListsOnHost(b.in(), {sorted.data(), nullptr, 0, nullptr, 0}, 1);
  std::vector<std::uint32_t> expected;
  for (std::uint32_t pair = 20; pair-- > 0;) expected.insert(expected.end(), {2 * pair, 2 * pair + 1});
  EXPECT_EQ(colorsOf(sorted), expected);
}

TEST(HostSort, ManyThreadsWriteTheWordsOfOne) {
  // 100,000 pixels of 1 to 5 fragments in scrambled depths, some tied: enough for several threads.
  std::vector<std::vector<std::array<std::uint32_t, 3>>> lists(100000);
  std::uint32_t state = 12345;
  const auto next = [&state] { return state = state * 1664525u + 1013904223u; };
  for (std::uint32_t p = 0; p < lists.size(); ++p)
    for (std::uint32_t i = 0, n = 1 + next() % 5; i < n; ++i) lists[p].push_back({next() % 4, next() % 3, p * 8 + i});
  const Blocks b(lists);
  std::vector<std::uint32_t> one(b.records.size()), many(b.records.size()), planeOne(b.records.size() / kStride),
      planeMany(planeOne.size());
  sortListsOnHost(b.in(), {one.data(), planeOne.data(), 2, nullptr, 0}, 1);
  sortListsOnHost(b.in(), {many.data(), planeMany.data(), 2, nullptr, 0}, 4);
  EXPECT_EQ(one, many);
  EXPECT_EQ(planeOne, planeMany);
  for (std::uint32_t p = 0; p < lists.size(); ++p)  // each list in (depth, triangle, record) order
    for (std::uint32_t i = 1; i < b.counts[p]; ++i) {
      const std::uint32_t* x = &one[(b.heads[p] + i - 1) * kStride];
      const std::uint32_t* y = &one[(b.heads[p] + i) * kStride];
      ASSERT_TRUE(x[0] < y[0] || (x[0] == y[0] && (x[1] < y[1] || (x[1] == y[1] && x[2] < y[2])))) << "pixel " << p;
    }
}
