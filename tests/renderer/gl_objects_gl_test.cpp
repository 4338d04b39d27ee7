// gpu::Buffer's GL-side writes and its reads through a staging buffer (issue #29's GPU table: on
// NVIDIA's driver a host write or read of a few bytes of a large buffer cost time in proportion to
// the buffer's size; the passes now leave such bytes to the GL and read them through 16 bytes).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "renderer/gpu/gl_objects.hpp"
#include "tests/support/gl_fixture.hpp"

using tlab::gpu::Buffer;

namespace {

std::vector<std::uint32_t> words(const Buffer& b) {
  std::vector<std::uint32_t> v(b.size() / 4);
  b.download(v.data(), b.size());
  return v;
}

Buffer counting(std::size_t n) {  // words 0, 1, 2, ...
  std::vector<std::uint32_t> v(n);
  std::iota(v.begin(), v.end(), 0u);
  return Buffer(n * 4, v.data());
}

}  // namespace

TEST(GlBuffer, SetFirstQuadWritesTheFirstFourWordsAndNothingElse) {
  const Buffer b = counting(1 << 16);
  b.setFirstQuad({7, 1, 1, 0xFFFFFFFFu});
  const auto v = words(b);
  EXPECT_EQ(std::vector<std::uint32_t>(v.begin(), v.begin() + 5), (std::vector<std::uint32_t>{7, 1, 1, 0xFFFFFFFFu, 4}));
  for (std::size_t i = 4; i < v.size(); ++i) ASSERT_EQ(v[i], i);
}

TEST(GlBuffer, FillWordsSetsThePrefixOnly) {
  const Buffer b = counting(100);
  b.fillWords(0x3F800000u, 37);  // 1.0f
  const auto v = words(b);
  for (std::size_t i = 0; i < v.size(); ++i) ASSERT_EQ(v[i], i < 37 ? 0x3F800000u : i) << i;
}

TEST(GlBuffer, DownloadThroughReadsTheRangeAtItsOffset) {
  const Buffer big = counting(1 << 18), staging(16);
  std::array<std::uint32_t, 4> got{};
  big.downloadThrough(staging, got.data(), 16);
  EXPECT_EQ(got, (std::array<std::uint32_t, 4>{0, 1, 2, 3}));
  std::uint32_t two[2] = {0, 0};
  big.downloadThrough(staging, two, 8, 4 * 200001);
  EXPECT_EQ(two[0], 200001u);
  EXPECT_EQ(two[1], 200002u);
  std::uint32_t one = 0;
  big.downloadThrough(staging, &one, 4, 12);  // a list's count (TransparencyFields::listCount)
  EXPECT_EQ(one, 3u);
  EXPECT_EQ(words(big)[12], 12u);  // the source is unchanged
  std::array<std::uint32_t, 5> tooMany{};
  EXPECT_THROW(big.downloadThrough(staging, tooMany.data(), 20), std::logic_error);
}
