// Stimulus-set files: what is read, and errors that name file:line:field.
#include <gtest/gtest.h>

#include "stimuli/sets/stimulus_set_file.hpp"
#include "stimuli/sets/stimulus_set_names.hpp"

namespace tlab::stimuli {
namespace {

std::string errorOf(const std::string& text) {
  try {
    parseStimulusSet(text, "set.toml");
  } catch (const StimulusSetError& e) {
    return e.what();
  }
  return "no error";
}

TEST(StimulusSetFile, ReadsStylesScenesViewsAndProbeSets) {
  const StimulusSetSpec spec = readStimulusSetFile(std::string(TLAB_TEST_DATA) + "/stimuli/small_set.toml");
  EXPECT_EQ(spec.name, "small");
  EXPECT_EQ(spec.width, 96);
  EXPECT_EQ(spec.seed, 5u);
  ASSERT_EQ(spec.styles.size(), 2u);
  EXPECT_EQ(spec.styles[1].name, "constant");
  EXPECT_EQ(spec.styles[1].settings.at("alpha"), "0.4");
  ASSERT_EQ(spec.scenes.size(), 3u);
  EXPECT_EQ(spec.scenes[0].views.size(), 2u);
  EXPECT_DOUBLE_EQ(spec.scenes[0].views[1].azimuthDegrees, 40.0);
  ASSERT_EQ(spec.scenes[0].probeSets.size(), 1u);
  EXPECT_EQ(spec.scenes[0].probeSets[0].spec.task, "points");
  EXPECT_EQ(spec.scenes[0].probeSets[0].spec.count, 2);
  EXPECT_EQ(spec.scenes[1].views.size(), 1u);  // the default view
  EXPECT_EQ(spec.scenes[1].place.line, 16);
}

TEST(StimulusSetFile, AnImagesEntryNamesItsPathsByTheScenesAndViewsNames) {
  const StimulusSetSpec spec = parseStimulusSet(R"([set]
styles = ["constant", { name = "theirs", images = "renders/{scene}-{view}.png" }]
[[scene]]
source = "builtin:nested-spheres?n=2"
views = [{}, { name = "side", azimuth = 30 }]
[[scene]]
source = "builtin:torus"
name = "ring"
)", "set.toml");
  ASSERT_EQ(spec.styles.size(), 2u);
  EXPECT_EQ(spec.styles[0].images, "");
  EXPECT_EQ(spec.styles[1].name, "theirs");
  EXPECT_EQ(spec.styles[1].images, "renders/{scene}-{view}.png");
  EXPECT_EQ(imagesPathFor(spec.styles[1].images, spec.scenes[0], 0), "renders/nested-spheres-v1.png");
  EXPECT_EQ(imagesPathFor(spec.styles[1].images, spec.scenes[0], 1), "renders/nested-spheres-side.png");
  EXPECT_EQ(imagesPathFor(spec.styles[1].images, spec.scenes[1], 0), "renders/ring-v1.png");
}

TEST(StimulusSetFile, AnImagesEntryWithAnUnknownPlaceholderOrSettingsNamesItsLine) {
  const std::string unknown = errorOf("[set]\nstyles = [\n  { name = \"t\", images = \"r/{scene}-{trial}.png\" },\n]\n[[scene]]\nsource = \"builtin:cube\"\n");
  EXPECT_EQ(unknown, "set.toml:3: set.styles[0].images: unknown placeholder {trial} (known: {scene}, {view})");
  const std::string settings = errorOf("[set]\nstyles = [{ name = \"t\", images = \"r/{scene}.png\", set = [\"alpha=1\"] }]\n[[scene]]\nsource = \"builtin:cube\"\n");
  EXPECT_NE(settings.find("set.toml:2: set.styles[0].set: an images entry shows another renderer's pictures: it has no settings"), std::string::npos) << settings;
  const std::string notPng = errorOf("[set]\nstyles = [{ name = \"t\", images = \"r/{scene}.jpg\" }]\n[[scene]]\nsource = \"builtin:cube\"\n");
  EXPECT_NE(notPng.find("set.toml:2: set.styles[0].images: expected a PNG path template"), std::string::npos) << notPng;
}

TEST(StimulusSetFile, AnUnknownStyleNamesItsLine) {
  const std::string e = errorOf("[set]\nstyles = [\n  \"opaque\",\n  \"nope\",\n]\n[[scene]]\nsource = \"builtin:cube\"\n");
  EXPECT_NE(e.find("set.toml:4: set.styles[1]"), std::string::npos) << e;
  EXPECT_NE(e.find("nope"), std::string::npos) << e;
}

TEST(StimulusSetFile, AMisspelledKeyNamesItsLineAndTheKnownKeys) {
  const std::string e = errorOf("[set]\nstyles = [\"opaque\"]\n[[scene]]\nsource = \"builtin:cube\"\nprobes = [\n  { task = \"points\", cuont = 2 },\n]\n");
  EXPECT_NE(e.find("set.toml:6: scene[0].probes[0].cuont: unknown key (known: count, seed, settings, task)"), std::string::npos) << e;
}

TEST(StimulusSetFile, WrongTypesAndRangesNameTheField) {
  EXPECT_NE(errorOf("[set]\nstyles = [\"opaque\"]\nsize = \"12 by 4\"\n[[scene]]\nsource = \"x\"\n").find("set.toml:3: set.size: expected WxH"),
            std::string::npos);
  EXPECT_NE(errorOf("[set]\nstyles = [\"opaque\"]\n[[scene]]\nsource = 3\n").find("set.toml:4: scene[0].source: expected a string"),
            std::string::npos);
  EXPECT_NE(errorOf("[set]\nstyles = [\"opaque\"]\n[[scene]]\nsource = \"x\"\nprobes = [{ task = \"points\", count = 0 }]\n")
                .find("set.toml:5: scene[0].probes[0].count: 0 is outside [1, 1000]"),
            std::string::npos);
  EXPECT_NE(errorOf("[set]\nstyles = [{ name = \"constant\", set = [\"alpha=7\"] }]\n[[scene]]\nsource = \"x\"\n").find("set.toml:2: set.styles[0]"),
            std::string::npos);
}

TEST(StimulusSetFile, SyntaxErrorsAndMissingPartsNameTheLine) {
  EXPECT_NE(errorOf("[set]\nstyles = [\"opaque\"\n").find("set.toml:"), std::string::npos);
  EXPECT_NE(errorOf("[set]\nname = \"x\"\n").find("set.toml:1: set.styles: missing"), std::string::npos);
  EXPECT_NE(errorOf("[set]\nstyles = [\"opaque\"]\n").find("scene: missing"), std::string::npos);
  EXPECT_NE(errorOf("[sett]\n").find("set.toml:1: sett: unknown key"), std::string::npos);
}

}  // namespace
}  // namespace tlab::stimuli
