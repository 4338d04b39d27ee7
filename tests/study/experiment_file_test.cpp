// The experiment file: what it holds after parsing, and one-line errors naming file:line and the
// field for every kind of bad input.
#include <gtest/gtest.h>

#include "study/experiment_file.hpp"
#include "tests/study/study_test_support.hpp"

using namespace tlab::study;

namespace {

const std::string kBase = R"(id = "x"
participants = 4
counterbalancing = "latin-square"
[[factors]]
name = "method"
levels = ["a", "b"]
[[tasks]]
task = "layer-index"
)";

std::string errorOf(const std::string& text) {
  try {
    parseExperiment(text, "bad.toml");
  } catch (const ExperimentFileError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(ExperimentFile, ReadsTheExamples) {
  const Experiment c = readExperimentFile(tlab::testing::example("carnecky2013.toml"));
  EXPECT_EQ(c.id, "carnecky2013");
  EXPECT_EQ(c.counterbalancing, Counterbalancing::GraecoLatin);
  EXPECT_EQ(c.blockTasks, BlockTasks::ByPosition);
  ASSERT_EQ(c.factors.size(), 2u);
  EXPECT_EQ(c.factors[0].levels[1].name, "normal-variation");
  EXPECT_EQ(c.factors[0].levels[1].style.value_or(""), "normal-variation");
  EXPECT_EQ(c.factors[1].levels[0].scene.value_or(""), "builtin:pretzel");
  ASSERT_EQ(c.tasks.size(), 3u);
  EXPECT_EQ(c.tasks[0].trialTimeLimitSeconds.value_or(0), 120.0);
  ASSERT_EQ(c.analyses.size(), 1u);
  EXPECT_EQ(c.analyses[0].within, std::vector<std::string>{"method"});
  EXPECT_EQ(c.questionnaires.at(0).items.size(), 2u);

  const Experiment e = readExperimentFile(tlab::testing::example("elmqvist.toml"));
  EXPECT_EQ(e.tasks.size(), 4u);
  EXPECT_EQ(e.tasks[1].scene.value_or(""), "builtin:abstract-pattern?letter={trial}&seed={trial}");
  EXPECT_EQ(e.tasks[3].when.at("scenario"), "walkthrough");
  EXPECT_EQ(e.factors[0].levels[1].style.value_or(""), "dynamic");  // parses before the style exists
}

TEST(ExperimentFile, ErrorsNameFileLineAndField) {
  EXPECT_EQ(errorOf("extra = 1\n" + kBase), "bad.toml:1: extra: unknown key (known: analysis, block_tasks, breaks, consent, counterbalancing, "
                                            "debrief, factors, goodbye, id, info, observer, participant_title, participants, "
                                            "questionnaires, seed, standard_info, stimulus, tasks, title, training, welcome)");
  EXPECT_EQ(errorOf(kBase + "trials = 0\n"), "bad.toml:9: tasks[1].trials: must be >= 1");
  EXPECT_NE(errorOf(kBase + "when = { method = \"c\" }\n").find("bad.toml:9: tasks[1].when.method: must name a level"),
            std::string::npos);
  EXPECT_NE(errorOf(kBase + "when = { colour = \"c\" }\n").find("tasks[1].when.colour: no factor of that name"), std::string::npos);
  EXPECT_NE(errorOf("id = \"x\"\nparticipants = 2\n[[tasks]]\ntask = \"juggling\"\n").find("bad.toml:4: tasks[1]: unknown task"),
            std::string::npos);
  EXPECT_NE(errorOf(kBase + "settings = [\"nonsense=1\"]\n").find("bad.toml:9: tasks[1]"), std::string::npos);
  EXPECT_EQ(errorOf("id = \"x\"\nparticipants = 2\nseed = \"seven\"\n[[tasks]]\ntask = \"layer-index\"\n"),
            "bad.toml:3: seed: must be an integer");
  EXPECT_NE(errorOf("id = \"x\"\nparticipants = [\n").find("bad.toml:"), std::string::npos);  // TOML syntax error
  EXPECT_EQ(errorOf("participants = 2\n[[tasks]]\ntask = \"layer-index\"\n").substr(0, 15), "bad.toml:1: id:");
  EXPECT_EQ(errorOf(kBase + "navigation = \"fly\"\n"), "bad.toml:9: tasks[1].navigation: navigation 'fly': expected none, orbit or walk");
  EXPECT_NE(errorOf(kBase + "navigation = \"orbit\"\n").find("bad.toml:9: tasks[1].navigation: only counting, pattern and target-discovery"),
            std::string::npos);
}

TEST(ExperimentFile, DesignConstraintsAreCheckedAgainstTheFile) {
  const std::string graeco = R"(id = "g"
participants = 3
counterbalancing = "graeco-latin"
[[factors]]
name = "a"
levels = ["1", "2", "3"]
[[factors]]
name = "b"
levels = ["1", "2"]
[[tasks]]
task = "layer-index"
)";
  EXPECT_EQ(errorOf(graeco),
            "bad.toml:3: counterbalancing: graeco-latin needs exactly two within factors with the same number of levels");
  const std::string six = R"(id = "g"
participants = 6
counterbalancing = "graeco-latin"
[[factors]]
name = "a"
levels = ["1", "2", "3", "4", "5", "6"]
[[factors]]
name = "b"
levels = ["1", "2", "3", "4", "5", "6"]
[[tasks]]
task = "layer-index"
)";
  EXPECT_NE(errorOf(six).find("no Graeco-Latin square of order 6 exists"), std::string::npos);
  EXPECT_NE(errorOf(kBase + "[[analysis]]\ndv = [\"speed\"]\n").find("bad.toml:10: analysis[1].dv: 'speed' is not one of"),
            std::string::npos);
  EXPECT_NE(errorOf(kBase + "[[factors]]\nname = \"method\"\nlevels = [\"c\", \"d\"]\n").find("factor 'method' is defined twice"),
            std::string::npos);
  EXPECT_NE(errorOf("id = \"x\"\nparticipants = 1\nblock_tasks = \"by-position\"\n[[tasks]]\ntask = \"layer-index\"\n[[tasks]]\n"
                    "task = \"counting\"\n")
                .find("\"by-position\" needs one task per block: 1 blocks but 2 tasks"),
            std::string::npos);
}
