#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/image.hpp"
#include "core/sha256.hpp"

using namespace tlab::core;

TEST(Image, PngBytesAreDeterministicAndRowZeroIsTheTop) {
  tlab::core::Image img(3, 2, glm::vec4(0, 0, 0, 1));
  img.at(0, 0) = glm::vec4(1, 0, 0, 1);
  const auto a = tlab::core::encodePng(img), b = tlab::core::encodePng(img);
  EXPECT_EQ(a, b);
  const auto rgba = tlab::core::toRgba8(img);
  EXPECT_EQ(rgba[0], 255);  // first pixel written = top-left
  EXPECT_EQ(rgba[4], 0);
}

TEST(Image, Rgba8RoundsAndClamps) {
  tlab::core::Image img(3, 1);
  img.at(0, 0) = glm::vec4(0.5f, -1.0f, 2.0f, 1.0f);
  const auto rgba = tlab::core::toRgba8(img);
  EXPECT_EQ(rgba[0], 128);
  EXPECT_EQ(rgba[1], 0);
  EXPECT_EQ(rgba[2], 255);
}

TEST(Image, Pgm16HeaderAndBigEndianSamples) {
  const auto pgm = tlab::core::encodePgm16({1, 258}, 2, 1);
  const std::string header = "P5\n2 1\n65535\n";
  ASSERT_EQ(pgm.size(), header.size() + 4);
  EXPECT_EQ(std::string(pgm.begin(), pgm.begin() + long(header.size())), header);
  EXPECT_EQ(pgm[header.size() + 0], 0);
  EXPECT_EQ(pgm[header.size() + 1], 1);
  EXPECT_EQ(pgm[header.size() + 2], 1);
  EXPECT_EQ(pgm[header.size() + 3], 2);
}

TEST(Image, AtomicWriteLeavesNoPartialFileOnFailure) {
  EXPECT_THROW(tlab::core::writeFileAtomically("/nonexistent-dir/x.png", {1, 2, 3}), std::runtime_error);
  const auto dir = std::filesystem::temp_directory_path() / "tlab_image_test";
  std::filesystem::create_directories(dir);
  const auto path = (dir / "a.bin").string();
  tlab::core::writeFileAtomically(path, {1, 2, 3});
  EXPECT_EQ(std::filesystem::file_size(path), 3u);
  for (const auto& e : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos);
}

// FIPS 180-4 test vectors (the empty string and "abc").
TEST(Sha256, MatchesTheStandardTestVectors) {
  EXPECT_EQ(tlab::core::sha256Hex(std::string_view()), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(tlab::core::sha256Hex(std::string_view("abc")), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  const std::vector<std::uint8_t> bytes = {'a', 'b', 'c'};
  EXPECT_EQ(tlab::core::sha256Hex(bytes), tlab::core::sha256Hex(std::string_view("abc")));
}
