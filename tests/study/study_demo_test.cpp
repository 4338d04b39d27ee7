#include "study/simulate/study_demo.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "study/design/counterbalancing.hpp"
#include "study/design/example_experiments.hpp"
#include "study/design/experiment_file.hpp"
#include "study/design/stimulus_size.hpp"

namespace tlab::study {
namespace {

TEST(StudyDemo, ExamplesAreEmbeddedAndParse) {
  for (const char* name : {"carnecky2013.toml", "elmqvist.toml"}) {
    const std::string text(exampleExperimentText(name));
    EXPECT_NO_THROW(parseExperiment(text, name)) << name;
  }
  EXPECT_THROW(exampleExperimentText("nope.toml"), std::runtime_error);
}

TEST(StudyDemo, ReducedSizeReplacesOnlyTheStimulusSize) {
  const std::string text(exampleExperimentText("carnecky2013.toml"));
  const Experiment original = parseExperiment(text, "carnecky2013.toml");
  const Experiment reduced = parseExperiment(withStimulusSize(text, "240x200"), "carnecky2013.toml");
  EXPECT_EQ(reduced.stimulus.width, 240);
  EXPECT_EQ(reduced.stimulus.height, 200);
  EXPECT_NE(original.stimulus.width, 240);
  EXPECT_EQ(reduced.tasks.size(), original.tasks.size());
  EXPECT_EQ(reduced.participants, original.participants);
}

TEST(StudyDemo, AStimulusSizeIsAddedWhereTheFileHasNone) {
  EXPECT_EQ(withStimulusSize("id = \"x\"\n", "240x200"), "id = \"x\"\n\n[stimulus]\nsize = \"240x200\"\n");
  EXPECT_EQ(withStimulusSize("id = \"x\"\n[stimulus]\nstyle = \"smart\"\n[[tasks]]\nsize = 3\n", "32x32"),
            "id = \"x\"\n[stimulus]\nsize = \"32x32\"\nstyle = \"smart\"\n[[tasks]]\nsize = 3\n");
  EXPECT_EQ(withStimulusSize("[stimulus]\nscene = \"builtin:sphere\"\n  size = \"64x64\"  \n", "32x48"),
            "[stimulus]\nscene = \"builtin:sphere\"\nsize = \"32x48\"\n");
}

TEST(StudyDemo, ElmqvistTasksAreInteractive) {
  const Experiment e = parseExperiment(std::string(exampleExperimentText("elmqvist.toml")), "elmqvist.toml");
  for (const auto& t : e.tasks) EXPECT_NE(t.navigation, Navigation::None) << t.id;
  EXPECT_EQ(e.task("T1")->navigation, Navigation::Orbit);
  EXPECT_EQ(e.task("T3")->navigation, Navigation::Walk);
}

// The annotated experiment file in the README is a working one.
TEST(StudyDemo, ReadmeExperimentExampleParses) {
  std::ifstream in(std::string(TLAB_SOURCE_DIR) + "/README.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string readme = text.str();
  const auto start = readme.find("```toml\n");
  ASSERT_NE(start, std::string::npos);
  const auto end = readme.find("```", start + 8);
  const std::string toml = readme.substr(start + 8, end - start - 8);
  const Experiment e = parseExperiment(toml, "README.md");
  EXPECT_EQ(e.id, "mystudy");
  EXPECT_EQ(e.factors.size(), 2u);
  EXPECT_EQ(e.tasks.at(0).questions, 10);
  EXPECT_NO_THROW(makeDesign(e));
}

}  // namespace
}  // namespace tlab::study
