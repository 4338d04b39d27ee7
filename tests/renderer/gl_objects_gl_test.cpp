// gpu::Buffer's GL-side writes and its reads through a staging buffer (issue #29's GPU table: on
// NVIDIA's driver a host write or read of a few bytes of a large buffer cost time in proportion to
// the buffer's size; the passes now leave such bytes to the GL and read them through 16 bytes);
// mapped reads, and which GLs run the passes that have a host-code twin as host code.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/gl_objects.hpp"
#include "tests/support/gl_fixture.hpp"
#include "tests/support/scoped_env.hpp"

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

TEST(GlBuffer, MappedReadShowsTheRangeAtItsOffsetAndUnmaps) {
  const Buffer b = counting(1 << 16);
  {
    const tlab::gpu::MappedRead view(b, 64, 4 * 1000);
    EXPECT_EQ(view.as<std::uint32_t>()[0], 1000u);
    EXPECT_EQ(view.as<std::uint32_t>()[15], 1015u);
  }
  b.fillWords(9u, 1);  // unmapped again: the GL may write it
  EXPECT_EQ(words(b)[0], 9u);
  const tlab::gpu::MappedRead again(b, 4);  // and map it again
  EXPECT_EQ(again.as<std::uint32_t>()[0], 9u);
}

// Which GLs run on the CPU (their GL_RENDERER strings), and TLAB_HOST_PASSES, which overrides it.
TEST(HostPasses, TheCpuRasterizersAndTheSwitch) {
  EXPECT_TRUE(tlab::gpu::rendererRunsOnCpu("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_TRUE(tlab::gpu::rendererRunsOnCpu("softpipe"));
  EXPECT_TRUE(tlab::gpu::rendererRunsOnCpu("ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)"));
  EXPECT_FALSE(tlab::gpu::rendererRunsOnCpu("NVIDIA H200/PCIe/SSE2"));
  EXPECT_FALSE(tlab::gpu::rendererRunsOnCpu("AMD Radeon RX 6800 (radeonsi, navi21, LLVM 15.0.6, DRM 3.49, 6.1.0)"));
  EXPECT_FALSE(tlab::gpu::rendererRunsOnCpu("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
  {
    const tlab::testing::ScopedEnv unset("TLAB_HOST_PASSES", nullptr);
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    ASSERT_NE(renderer, nullptr);
    EXPECT_EQ(tlab::gpu::hostPassesWanted(), tlab::gpu::rendererRunsOnCpu(renderer)) << renderer;
  }
  {
    const tlab::testing::ScopedEnv off("TLAB_HOST_PASSES", "off");
    EXPECT_FALSE(tlab::gpu::hostPassesWanted());
  }
  {
    const tlab::testing::ScopedEnv on("TLAB_HOST_PASSES", "on");
    EXPECT_TRUE(tlab::gpu::hostPassesWanted());
  }
  const tlab::testing::ScopedEnv wrong("TLAB_HOST_PASSES", "yes");
  try {
    tlab::gpu::hostPassesWanted();
    ADD_FAILURE() << "TLAB_HOST_PASSES=yes was accepted";
  } catch (const tlab::gpu::GlError& e) {
    EXPECT_STREQ(e.what(), "TLAB_HOST_PASSES must be auto, on or off, not 'yes'");
  }
}
