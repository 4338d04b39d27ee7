// `tlab report study.db` as a researcher reads it (issue 15, part 6): a warning at the top when the
// participants were simulated (with what a simulated observer is), each method note once, the
// questionnaire answers and the stimuli shown, tasks analysed one by one unless they cannot be (then
// pooled with a note saying why), and the output folder created as `export` creates its folder.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;

namespace {

const std::string kTlab = TLAB_EXE;

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

std::string simulate(const std::filesystem::path& dir, const std::string& experiment, int participants) {
  const std::string db = (dir / "sim.db").string();
  const auto sim = runCommand(kTlab + " simulate " + studyData(experiment) + " --participants " + std::to_string(participants) + " --db " + db);
  EXPECT_EQ(sim.exitCode, 0) << sim.err;
  return db;
}

}  // namespace

TEST(StudyReportCli, SimulatedDataQuestionnairesStimuliAndNotesOnce) {
  const auto dir = freshDir("study_report_cli");
  const std::string db = simulate(dir, "tiny.toml", 4);
  const auto out = dir / "no" / "such" / "folder" / "r.html";
  const auto report = runCommand(kTlab + " report " + db + " -o " + out.string() + " --markdown " + (dir / "md" / "r.md").string());
  ASSERT_EQ(report.exitCode, 0) << report.err;
  ASSERT_TRUE(std::filesystem::exists(out));
  const std::string html = readText(out.string());
  const std::size_t warning = html.find("SIMULATED DATA: All 4 participants in this report are simulated observers");
  ASSERT_NE(warning, std::string::npos);
  EXPECT_LT(warning, html.find("<table"));
  EXPECT_NE(html.find("local RMS luminance contrast c in a 9x9-pixel window"), std::string::npos);
  EXPECT_EQ(count(html, "ANOVA sums of squares: type II"), 1u);  // two dependent variables, one note
  EXPECT_EQ(count(html, "Outlier screening: Tukey fences"), 1u);
  EXPECT_NE(html.find("Questionnaire 'post'"), std::string::npos) << html.substr(0, 400);
  EXPECT_NE(html.find("ease: The task was easy."), std::string::npos);
  EXPECT_NE(html.find("Stimuli shown"), std::string::npos);
  EXPECT_NE(html.find("-stimuli/"), std::string::npos);  // the stimulus files
  EXPECT_NE(html.find("<figure><img alt=\"layer: method=alpha, scene=cylinders\""), std::string::npos);  // and the pictures
  EXPECT_NE(html.find("data:image/png;base64,"), std::string::npos);
  const std::string md = readText((dir / "md" / "r.md").string());
  EXPECT_EQ(md.find("> **SIMULATED DATA"), md.find("\n\n") + 2);  // right under the title

  const auto analyze = runCommand(kTlab + " analyze " + db);
  ASSERT_EQ(analyze.exitCode, 0) << analyze.err;
  EXPECT_NE(analyze.out.find("SIMULATED DATA: All 4 participants"), std::string::npos) << analyze.out;

  // A folder that cannot be created: one plain line naming it.
  std::filesystem::create_directories(dir / "ro");
  { std::ofstream file(dir / "ro" / "file"); }
  const auto bad = runCommand(kTlab + " report " + db + " -o " + (dir / "ro" / "file" / "r.html").string());
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.err.find("cannot create the folder for r.html"), std::string::npos) << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
}

TEST(StudyReportCli, TasksAreAnalysedOneByOneUnlessTheyCannotBe) {
  const auto dir = freshDir("study_report_tasks");
  const std::string db = simulate(dir, "two_tasks.toml", 4);
  const auto report = runCommand(kTlab + " report " + db + " -o " + (dir / "r.html").string());
  ASSERT_EQ(report.exitCode, 0) << report.err;
  const std::string html = readText((dir / "r.html").string());
  EXPECT_NE(html.find("<h2>correct [task front]</h2>"), std::string::npos);
  EXPECT_NE(html.find("<h2>correct [task again]</h2>"), std::string::npos);
  EXPECT_NE(html.find("correct: analysed per task (front, again)"), std::string::npos);

  const auto pooledDir = freshDir("study_report_pooled");
  const std::string pooledDb = simulate(pooledDir, "two_tasks_by_position.toml", 4);
  const auto pooled = runCommand(kTlab + " report " + pooledDb + " -o " + (pooledDir / "r.html").string());
  ASSERT_EQ(pooled.exitCode, 0) << pooled.err;
  const std::string pooledHtml = readText((pooledDir / "r.html").string());
  EXPECT_NE(pooledHtml.find("<h2>correct</h2>"), std::string::npos);
  EXPECT_NE(pooledHtml.find("correct: pooled over the tasks front, again because task 'front' cannot be analysed alone"),
            std::string::npos);
}

// tests = ["mixed"] (issue 31): each task gets its mixed model even though no task can be analysed
// alone by the ANOVA or t-tests; the report names the model exactly, shows the fixed effects and
// variance components, the pairwise p-values are Holm-adjusted, and formula = "..." overrides.
TEST(StudyReportCli, MixedModelsPerTaskHolmCorrectionAndFormula) {
  const auto dir = freshDir("study_report_mixed");
  const std::string db = simulate(dir, "mixed_plan.toml", 12);
  const auto report = runCommand(kTlab + " report " + db + " -o " + (dir / "r.html").string());
  ASSERT_EQ(report.exitCode, 0) << report.err;
  const std::string html = readText((dir / "r.html").string());
  for (const char* task : {"front", "again", "third"}) {
    EXPECT_NE(html.find(std::string(">correct [task ") + task + "]: mixed model</h"), std::string::npos) << task;
    EXPECT_NE(html.find(std::string(">rt [task ") + task + "]: mixed model</h"), std::string::npos) << task;
  }
  EXPECT_NE(html.find("binomial family with logit link, fit by maximum likelihood with the Laplace approximation (lme4 formula "
                      "correct ~ method + (1 | participant) + (1 | stimulus)"),
            std::string::npos);
  EXPECT_NE(html.find("linear mixed model fit by REML (lme4 formula log(rt) ~ method + (1 | participant) + (1 | stimulus)"),
            std::string::npos);
  EXPECT_NE(html.find("The stimulus is the image shown (its SHA-256)."), std::string::npos);
  EXPECT_NE(html.find("<caption>Fixed effects</caption>"), std::string::npos);
  EXPECT_NE(html.find("<caption>Random effects (variance components)</caption>"), std::string::npos);
  EXPECT_NE(html.find("the mixed model analyses each task alone"), std::string::npos);
  EXPECT_NE(html.find("holm-adjusted p = "), std::string::npos);
  // The second [[analysis]], with its own formula, is a section of the same page (one report per invocation).
  EXPECT_FALSE(std::filesystem::exists(dir / "r-2.html"));
  EXPECT_NE(html.find("(lme4 formula rt ~ method + (1 | participant);"), std::string::npos);

  const auto analyze = runCommand(kTlab + " analyze " + db + " --json");
  ASSERT_EQ(analyze.exitCode, 0) << analyze.err;
  const auto j = nlohmann::json::parse(analyze.out);
  const auto& first = j["analyses"][0];
  ASSERT_EQ(first["mixed_models"].size(), 6u);  // correct and rt, three tasks each
  for (const auto& m : first["mixed_models"]) {
    EXPECT_EQ(m["fixed_effects"].size(), 3u);
    EXPECT_EQ(m["fixed_effects"][1]["term"], "methodsmart");  // the experiment's level order: alpha is the reference
    EXPECT_TRUE(m.contains("warnings"));
  }
  ASSERT_FALSE(first["pairwise"].empty());
  for (const auto& p : first["pairwise"]) {
    EXPECT_EQ(p["correction"], "holm");
    EXPECT_GE(p["p_adjusted"].get<double>(), p["p"].get<double>());
  }
  EXPECT_EQ(j["analyses"][1]["mixed_models"][0]["formula"], "rt ~ method + (1 | participant)");
}
