#include "study/study_demo.hpp"

#include <gtest/gtest.h>

#include "study/example_experiments.hpp"
#include "study/experiment_file.hpp"

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
  EXPECT_THROW(withStimulusSize("id = \"x\"\n", "240x200"), std::invalid_argument);
}

TEST(StudyDemo, ElmqvistTasksAreInteractive) {
  const Experiment e = parseExperiment(std::string(exampleExperimentText("elmqvist.toml")), "elmqvist.toml");
  for (const auto& t : e.tasks) EXPECT_NE(t.navigation, Navigation::None) << t.id;
  EXPECT_EQ(e.task("T1")->navigation, Navigation::Orbit);
  EXPECT_EQ(e.task("T3")->navigation, Navigation::Walk);
}

}  // namespace
}  // namespace tlab::study
