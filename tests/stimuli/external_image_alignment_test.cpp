// The alignment check of images from another renderer on masks with known answers: an ellipse
// against itself flipped, moved, enlarged and stretched, and an image's background found from its
// corners or its alpha.
#include <gtest/gtest.h>

#include "stimuli/sets/external_image_alignment.hpp"

using namespace tlab::stimuli;

namespace {

// An axis-aligned ellipse centred at (cx, cy) with half-axes (rx, ry), in a 120×90 mask.
CoverageMask ellipse(double cx, double cy, double rx, double ry) {
  CoverageMask m{120, 90, std::vector<std::uint8_t>(120 * 90, 0)};
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      const double u = (x + 0.5 - cx) / rx, v = (y + 0.5 - cy) / ry;
      m.covered[std::size_t(y) * m.width + x] = u * u + v * v <= 1.0;
    }
  return m;
}

// An egg shape (not symmetric top to bottom) so that a flip shows.
CoverageMask egg() {
  CoverageMask m = ellipse(60, 40, 30, 20);
  const CoverageMask lower = ellipse(60, 55, 18, 22);
  for (std::size_t i = 0; i < m.covered.size(); ++i) m.covered[i] = m.covered[i] || lower.covered[i];
  return m;
}

}  // namespace

TEST(ExternalImageAlignment, IdenticalCoverageHasIouOne) {
  const auto r = compareCoverage(egg(), egg());
  EXPECT_EQ(r.iou, 1.0);
  EXPECT_TRUE(r.aligned);
  EXPECT_EQ(r.likelyCause, "");
}

TEST(ExternalImageAlignment, IouIsIntersectionOverUnion) {
  CoverageMask a{4, 1, {1, 1, 0, 0}}, b{4, 1, {0, 1, 1, 0}};
  EXPECT_DOUBLE_EQ(intersectionOverUnion(a, b), 1.0 / 3.0);
}

TEST(ExternalImageAlignment, EachMistakeIsNamed) {
  const CoverageMask ours = egg();
  CoverageMask flipped = ours;
  for (int y = 0; y < ours.height; ++y)
    for (int x = 0; x < ours.width; ++x) flipped.covered[std::size_t(ours.height - 1 - y) * 120 + x] = ours.covered[std::size_t(y) * 120 + x];
  const auto f = compareCoverage(ours, flipped);
  EXPECT_LT(f.iou, 0.98);
  EXPECT_EQ(f.likelyCause.rfind("vertical flip", 0), 0u) << f.likelyCause;

  const auto moved = compareCoverage(ellipse(60, 45, 30, 20), ellipse(70, 45, 30, 20));
  EXPECT_LT(moved.iou, 0.98);
  EXPECT_EQ(moved.likelyCause.rfind("shifted camera (the scene appears moved by 10, 0 pixels", 0), 0u) << moved.likelyCause;

  // Moved so far that the image's border cuts the scene off: still a shift, not an aspect change.
  const auto cut = compareCoverage(ellipse(40, 45, 38, 30), ellipse(20, 45, 38, 30));
  EXPECT_EQ(cut.likelyCause.rfind("shifted camera (the scene appears moved by -20, 0 pixels", 0), 0u) << cut.likelyCause;

  const auto wider = compareCoverage(ellipse(60, 45, 30, 20), ellipse(60, 45, 36, 24));
  EXPECT_LT(wider.iou, 0.98);
  EXPECT_EQ(wider.likelyCause.rfind("field of view", 0), 0u) << wider.likelyCause;

  const auto stretched = compareCoverage(ellipse(60, 45, 30, 20), ellipse(60, 45, 38, 20));
  EXPECT_LT(stretched.iou, 0.98);
  EXPECT_EQ(stretched.likelyCause.rfind("aspect", 0), 0u) << stretched.likelyCause;

  const auto empty = compareCoverage(ours, CoverageMask{120, 90, std::vector<std::uint8_t>(120 * 90, 0)});
  EXPECT_EQ(empty.iou, 0.0);
  EXPECT_EQ(empty.likelyCause, "the image shows nothing but background");
}

TEST(ExternalImageAlignment, TheBackgroundIsTheCornersColourOrTransparency) {
  tlab::core::Image image(4, 3, glm::vec4(0.2f, 0.3f, 0.4f, 1.0f));
  image.at(1, 1) = glm::vec4(0.9f, 0.3f, 0.4f, 1.0f);
  image.at(2, 1) = glm::vec4(0.22f, 0.31f, 0.4f, 1.0f);  // within 0.05 of the background
  image.at(3, 2) = glm::vec4(1.0f);                     // one corner differs: three agree
  auto m = imageCoverage(image);
  EXPECT_EQ(m.covered, (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1}));
  image.at(0, 0).a = 0.0f;  // transparency decides once the image has any
  m = imageCoverage(image);
  EXPECT_EQ(m.count(), 11u);
  EXPECT_EQ(m.covered[0], 0);
}
