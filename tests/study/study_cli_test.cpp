// End to end through `tlab`: design tables of the examples, a simulated study with progress
// lines, analysis (text and JSON), CSV export, the HTML report of a database, dropouts, refusing
// a second run of a finished participant, and one-line errors for bad input.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;

namespace {

const std::string kTlab = TLAB_EXE;

void expectOneLineError(const CommandResult& r, const std::string& part) {
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_EQ(r.err.rfind("tlab: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
}

}  // namespace

// The tables alone (--quick): the stimulus and plan checks of the examples run in
// ShippedExample.DesignsAndSimulates.
TEST(StudyCli, DesignPrintsTheAssignmentTables) {
  const auto c = runCommand(kTlab + " design --quick " + example("carnecky2013.toml"));
  ASSERT_EQ(c.exitCode, 0) << c.err;
  EXPECT_NE(c.out.find("counterbalancing graeco-latin: 3 order rows"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("participants 36: balanced"), std::string::npos);
  EXPECT_NE(c.out.find("method=smart, scene=toroid [nearest-point]"), std::string::npos);
  const auto e = runCommand(kTlab + " design --quick " + example("elmqvist.toml"));
  ASSERT_EQ(e.exitCode, 0) << e.err;
  EXPECT_NE(e.out.find("test records in total: 384"), std::string::npos) << e.out;
  const auto unbalanced = runCommand(kTlab + " design --quick " + example("elmqvist.toml") + " --participants 6");
  EXPECT_EQ(unbalanced.out.find("checking the stimuli"), std::string::npos) << "--quick skips the rendering";
  EXPECT_NE(unbalanced.out.find("NOT balanced"), std::string::npos);
}

TEST(StudyCli, SimulateAnalyzeExportReportAndRefusals) {
  const auto dir = freshDir("study_cli");
  const std::string db = (dir / "sim.db").string();
  const auto sim = runCommand(kTlab + " simulate " + studyData("tiny.toml") + " --participants 8 --db " + db);
  ASSERT_EQ(sim.exitCode, 0) << sim.err;
  EXPECT_NE(sim.out.find("participant sim-008: slot 7, 10 trials"), std::string::npos) << sim.out;
  EXPECT_NE(sim.out.find("simulated 8 participants, 80 trials in"), std::string::npos) << sim.out;

  const auto again = runCommand(kTlab + " simulate " + studyData("tiny.toml") + " --participants 8 --db " + db);
  expectOneLineError(again, "already holds simulated participant 'sim-001'; continue with --resume");
  const auto resumed = runCommand(kTlab + " simulate " + studyData("tiny.toml") + " --participants 9 --db " + db + " --resume");
  ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("simulated 1 participants, 10 trials"), std::string::npos) << resumed.out;

  // A finished participant is refused before any window is opened (no DISPLAY needed).
  const auto second = runCommand("env -u DISPLAY " + kTlab + " run " + studyData("tiny.toml") + " --participant sim-001 --db " + db);
  expectOneLineError(second, "participant 'sim-001' has already finished experiment 'tiny'; a second run is refused");
  const auto noResume = runCommand("env -u DISPLAY " + kTlab + " run " + studyData("tiny.toml") + " --participant nobody --resume --db " + db);
  expectOneLineError(noResume, "participant 'nobody' has no session to resume");

  const auto text = runCommand(kTlab + " analyze " + db);
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("ANOVA method:scene"), std::string::npos) << text.out;
  const auto json = runCommand(kTlab + " analyze " + db + " --json");
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const auto j = nlohmann::json::parse(json.out);
  ASSERT_EQ(j["analyses"].size(), 1u);
  EXPECT_EQ(j["analyses"][0]["subjects"], 9);
  EXPECT_EQ(j["analyses"][0]["dependent_variables"].size(), 2u);
  EXPECT_EQ(j["analyses"][0]["dependent_variables"][0]["anova"]["effects"].size(), 3u);

  const auto exported = runCommand(kTlab + " export " + db + " --csv " + (dir / "csv").string());
  ASSERT_EQ(exported.exitCode, 0) << exported.err;
  const auto rows = parseCsv(readText((dir / "csv" / "trials.csv").string()));
  ASSERT_EQ(rows.size(), 1u + 9 * 10);
  EXPECT_EQ(rows[0][0], "experiment");
  EXPECT_EQ(rows[1][1], "sim-001");
  EXPECT_EQ(parseCsv(readText((dir / "csv" / "questionnaires.csv").string())).size(), 1u + 9);
  EXPECT_EQ(parseCsv(readText((dir / "csv" / "participants.csv").string())).size(), 1u + 9);

  const auto report = runCommand(kTlab + " report " + db + " -o " + (dir / "report.html").string());
  ASSERT_EQ(report.exitCode, 0) << report.err;
  const std::string html = readText((dir / "report.html").string());
  EXPECT_NE(html.find("Correct answers by method"), std::string::npos);
  EXPECT_NE(html.find("data:image/svg+xml;base64,"), std::string::npos);

  const auto drop = runCommand(kTlab + " drop " + db + " --participant sim-003 --reason test");
  ASSERT_EQ(drop.exitCode, 0) << drop.err;
  const auto design = runCommand(kTlab + " design " + studyData("tiny.toml") + " --db " + db);
  EXPECT_NE(design.out.find("sim-003      dropped"), std::string::npos) << design.out;
  const auto json2 = nlohmann::json::parse(runCommand(kTlab + " analyze " + db + " --json").out);
  EXPECT_EQ(json2["analyses"][0]["subjects"], 8);  // the dropped participant is left out
}

TEST(StudyCli, BadInputsGiveOneLineErrors) {
  const auto dir = freshDir("study_cli_bad");
  expectOneLineError(runCommand(kTlab + " design " + (dir / "missing.toml").string()), "cannot open the experiment file");
  {
    std::ofstream bad(dir / "bad.toml");
    bad << "id = \"x\"\nparticipants = 0\n[[tasks]]\ntask = \"layer-index\"\n";
  }
  expectOneLineError(runCommand(kTlab + " design " + (dir / "bad.toml").string()), "bad.toml:2: participants: must be >= 1");
  expectOneLineError(runCommand(kTlab + " export " + (dir / "none.db").string() + " --csv " + dir.string()), "no such database");
  expectOneLineError(runCommand(kTlab + " analyze " + (dir / "none.db").string()), "no such database");
  expectOneLineError(runCommand(kTlab + " simulate " + studyData("tiny.toml") + " --db " + (dir / "s.db").string() + " --pace -1"),
                     "--pace: must be >= 0");
  {
    std::ofstream bad(dir / "scene.toml");
    bad << "id = \"x\"\nparticipants = 1\n[stimulus]\nscene = \"builtin:no-such-scene\"\n[[tasks]]\ntask = \"layer-index\"\n";
  }
  expectOneLineError(runCommand(kTlab + " simulate " + (dir / "scene.toml").string() + " --db " + (dir / "s2.db").string()), "no-such-scene");
}
