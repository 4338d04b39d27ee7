// compose/host_blend.hpp: constant's front-to-back blending as host code (issue #29), on hand-made
// lists whose pictures follow from Carnecky's blending equation; the pictures the shader draws
// are compared float for float in IllustrationBuffer.ConstantSortingInItsComposePassEqualsTheSortPass.
#include <gtest/gtest.h>

#include <vector>

#include "renderer/compose/host_blend.hpp"

using tlab::render::blendOnHost;
using tlab::render::SortedColours;

namespace {

// packUnorm4x8 of whole bytes.
std::uint32_t rgba(std::uint32_t r, std::uint32_t g, std::uint32_t b) { return r | g << 8 | b << 16 | 0xFFu << 24; }

}  // namespace

// A 3×2 image (GL rows: row 0 at the bottom): pixel (0, 0) holds white in front of red, (2, 1)
// blue alone, the others nothing. With α = 0.5 and a grey background g:
// white-then-red: c = 0.5·1 + 0.25·(1, 0, 0), T = 0.25, so (0.75, 0.5, 0.5) + 0.25·g.
TEST(HostBlend, ListsBlendFrontToBackOverTheBackground) {
  const std::vector<std::uint32_t> counts{2, 0, 0, 0, 0, 1}, heads{0, 2, 2, 2, 2, 2};
  const std::vector<std::uint32_t> plane{rgba(255, 255, 255), rgba(255, 0, 0), rgba(0, 0, 255)};
  const glm::vec3 grey(0.25f);
  for (const unsigned threads : {1u, 4u}) {
    tlab::core::Image image(3, 2, glm::vec4(9.0f));
    blendOnHost({counts.data(), heads.data(), plane.data(), 3, 2}, 0, 0, 3, 2, 0.5f, grey, image, threads);
    EXPECT_EQ(image.at(0, 1), glm::vec4(0.75f + 0.0625f, 0.5f + 0.0625f, 0.5f + 0.0625f, 1.0f)) << "GL row 0 is the image's last";
    EXPECT_EQ(image.at(2, 0), glm::vec4(0.125f, 0.125f, 0.5f + 0.125f, 1.0f));
    EXPECT_EQ(image.at(1, 0), glm::vec4(grey, 1.0f)) << "an empty pixel is the background";
    EXPECT_EQ(image.at(1, 1), glm::vec4(grey, 1.0f));
  }
}

// Only the rectangle is blended (the scene's footprint); the pixels outside it are the background
// whatever their lists hold, and a rectangle reaching past the image is cut to it.
TEST(HostBlend, PixelsOutsideTheRectangleAreTheBackground) {
  const std::vector<std::uint32_t> counts{1, 1, 1, 1}, heads{0, 1, 2, 3};
  const std::vector<std::uint32_t> plane(4, rgba(255, 255, 255));
  const glm::vec3 black(0.0f);
  tlab::core::Image image(2, 2);
  blendOnHost({counts.data(), heads.data(), plane.data(), 2, 2}, 1, -3, 5, 1, 1.0f, black, image, 2);
  EXPECT_EQ(image.at(1, 1), glm::vec4(1.0f)) << "GL (1, 0): inside, opaque white";
  EXPECT_EQ(image.at(0, 1), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)) << "GL (0, 0): left of the rectangle";
  EXPECT_EQ(image.at(0, 0), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  EXPECT_EQ(image.at(1, 0), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)) << "GL (1, 1): above the rectangle";
  tlab::core::Image empty(2, 2, glm::vec4(5.0f));
  blendOnHost({counts.data(), heads.data(), plane.data(), 2, 2}, 2, 0, 2, 2, 1.0f, black, empty, 2);  // no pixel
  for (const auto& p : empty.pixels) EXPECT_EQ(p, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
}
