// FragmentLayout: where each property sits in a record, and the padding of records of 4 words or
// more to whole quads of words (issue #29: the fill and the sort then move them as uvec4s).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>

#include "renderer/buffer/fragment_layout.hpp"

namespace tlab::render {
namespace {

FragmentProperties with(std::initializer_list<FragmentProperty> list) {
  FragmentProperties p;
  for (FragmentProperty f : list) p |= f;
  return p;
}

std::string defineOf(const FragmentLayout& layout, const std::string& name) {
  const auto d = layout.defines();
  const auto it = std::find_if(d.begin(), d.end(), [&](const auto& kv) { return kv.first == name; });
  return it == d.end() ? "(none)" : it->second;
}

TEST(FragmentLayout, RecordsOfThreeWordsOrFewerAreNotPadded) {
  const FragmentLayout bare({});
  EXPECT_EQ(bare.stride, 2u);
  EXPECT_EQ(bare.quads, 0u);
  const FragmentLayout colour(with({FragmentProperty::Color}));  // constant's record
  EXPECT_EQ(colour.stride, 3u);
  EXPECT_EQ(colour.words, 3u);
  EXPECT_EQ(colour.quads, 0u);
  EXPECT_EQ(colour.colorOffset, 2u);
  EXPECT_EQ(defineOf(colour, "TLAB_STRIDE"), "3u");
  EXPECT_EQ(defineOf(colour, "TLAB_RECORD_QUADS"), "(none)");
}

TEST(FragmentLayout, LongerRecordsArePaddedToWholeQuadsWithTheirOffsetsUnchanged) {
  // smart's record: depth, triangle, colour, normal, gradient (6 words) and the ids (7) -> 8.
  for (const bool ids : {false, true}) {
    FragmentProperties p = with({FragmentProperty::Color, FragmentProperty::Normal, FragmentProperty::DepthGradient});
    if (ids) p |= FragmentProperty::Ids;
    const FragmentLayout smart(p);
    EXPECT_EQ(smart.stride, 8u);
    EXPECT_EQ(smart.words, ids ? 7u : 6u);  // the words the properties take, without the padding
    EXPECT_EQ(smart.quads, 2u);
    EXPECT_EQ(smart.colorOffset, 2u);
    EXPECT_EQ(smart.normalOffset, 3u);
    EXPECT_EQ(smart.depthGradientOffset, 4u);
    if (ids) {
      EXPECT_EQ(smart.idsOffset, 6u);
    }
    EXPECT_EQ(defineOf(smart, "TLAB_STRIDE"), "8u");
    EXPECT_EQ(defineOf(smart, "TLAB_RECORD_QUADS"), "2u");
  }
  const FragmentLayout four(with({FragmentProperty::Color, FragmentProperty::Normal}));  // a whole quad: no padding
  EXPECT_EQ(four.stride, 4u);
  EXPECT_EQ(four.words, 4u);
  EXPECT_EQ(four.quads, 1u);
  // Every property: 2 + 1 + 1 + 2 + 1 + 2 + 2 + 4 = 15 words -> 16; (s, t)'s gradient straddles quads 2 and 3.
  const FragmentLayout all(with({FragmentProperty::Color, FragmentProperty::Normal, FragmentProperty::DepthGradient,
                                 FragmentProperty::Ids, FragmentProperty::SurfaceParams,
                                 FragmentProperty::NormalZGradient, FragmentProperty::StGradient}));
  EXPECT_EQ(all.stride, 16u);
  EXPECT_EQ(all.words, 15u);
  EXPECT_EQ(all.quads, 4u);
  EXPECT_EQ(all.stGradientOffset, 11u);
}

}  // namespace
}  // namespace tlab::render
