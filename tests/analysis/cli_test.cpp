// End-to-end: run the tlab binary as a user would on the CSV files in tests/data/analysis and
// parse its JSON. Expected numbers are the R values of the unit tests (R 4.2.2 t.test,
// anova, wilcox.test, friedman.test; car::Anova), so CLI plumbing errors (wrong level order, wrong
// column, lost precision) show up here.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

using testing::relativelyNear;

struct RunResult {
  int exitCode = -1;
  std::string output;
};

RunResult runTlab(const std::string& arguments, bool mergeStderr = false) {
  const std::string command = std::string(TLAB_EXE) + " " + arguments + (mergeStderr ? " 2>&1" : " 2>/dev/null");
  RunResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string data(const char* name) { return std::string(TLAB_TEST_DATA) + "/analysis/" + name; }

nlohmann::json runJson(const std::string& arguments) {
  const RunResult r = runTlab(arguments);
  EXPECT_EQ(r.exitCode, 0) << arguments << "\n" << r.output;
  return nlohmann::json::parse(r.output);
}

TEST(Cli, TTestWelchPairedStudent) {
  // R: t.test(extra ~ group, sleep) and the paired test (see ttest_test.cpp).
  const auto welch = runJson("stats ttest " + data("sleep.csv") + " --dv extra --between group --json");
  EXPECT_EQ(welch["test"], "welch");
  EXPECT_TRUE(relativelyNear(welch["t"].get<double>(), -1.86081346748685, 1e-10));
  EXPECT_TRUE(relativelyNear(welch["df"].get<double>(), 17.7764735161785, 1e-10));
  EXPECT_TRUE(relativelyNear(welch["p"].get<double>(), 0.0793941401873582, 1e-10));
  EXPECT_TRUE(relativelyNear(welch["mean_diff"].get<double>(), -1.58, 1e-13));
  EXPECT_TRUE(relativelyNear(welch["ci_low"].get<double>(), -3.36548323071171, 1e-10));
  EXPECT_TRUE(relativelyNear(welch["ci_high"].get<double>(), 0.20548323071171, 1e-10));
  EXPECT_TRUE(relativelyNear(welch["d"].get<double>(), -0.83218108134954, 1e-10));
  const auto paired = runJson("stats ttest " + data("sleep.csv") + " --dv extra --within group --subject ID --json");
  EXPECT_EQ(paired["test"], "paired");
  EXPECT_TRUE(relativelyNear(paired["t"].get<double>(), -4.06212768338204, 1e-10));
  EXPECT_EQ(paired["df"].get<double>(), 9.0);
  const auto student = runJson("stats ttest " + data("sleep.csv") + " --dv extra --between group --student "
                               "--alternative less --json");
  EXPECT_EQ(student["test"], "student");
  EXPECT_EQ(student["df"].get<double>(), 18.0);
  EXPECT_TRUE(relativelyNear(student["p"].get<double>(), 0.0791867142159382 / 2, 1e-10));
}

TEST(Cli, AnovaJsonFields) {
  // R: PlantGrowth F = 4.84608786238014 (2, 27); rm_oneway.csv: ε_GG = 0.548761076845484.
  const auto plant = runJson("stats anova " + data("plant_growth.csv") + " --dv weight --between group --json");
  ASSERT_EQ(plant["effects"].size(), 1u);
  EXPECT_EQ(plant["effects"][0]["effect"], "group");
  EXPECT_TRUE(relativelyNear(plant["effects"][0]["F"].get<double>(), 4.84608786238014, 1e-10));
  EXPECT_EQ(plant["effects"][0]["df2"].get<double>(), 27.0);
  EXPECT_FALSE(plant["effects"][0].contains("eps_gg"));
  const auto rm = runJson("stats anova " + data("rm_oneway.csv") + " --dv score --within condition --subject subject --json");
  const auto& e = rm["effects"][0];
  for (const char* key : {"effect", "F", "df1", "df2", "p", "eps_gg", "eps_hf", "p_gg", "p_hf", "mauchly_w",
                          "mauchly_p", "eta2_partial", "eta2_generalized"})
    EXPECT_TRUE(e.contains(key)) << key;
  EXPECT_TRUE(relativelyNear(e["eps_gg"].get<double>(), 0.548761076845484, 1e-10));
  // car::Anova type III on the mixed data: time F = 71.6928104575164.
  const auto mixed = runJson("stats anova " + data("mixed.csv") + " --dv y --between g --within time --subject s "
                             "--ss-type 3 --json");
  EXPECT_EQ(mixed["effects"][1]["effect"], "time");
  EXPECT_TRUE(relativelyNear(mixed["effects"][1]["F"].get<double>(), 71.6928104575164, 1e-10));
}

TEST(Cli, RankTests) {
  // R: wilcox.test(x, y, paired = TRUE) on sleep: V = 0, p = 0.00909069801592506;
  // wilcox.test(extra ~ group, sleep): W = 25.5, p = 0.0693275754336266;
  // friedman.test on the 8 × 4 matrix of rm_oneway.csv: chi-squared = 21.6, df = 3,
  // p = 7.90046165867983e-05.
  const auto w = runJson("stats wilcoxon " + data("sleep.csv") + " --dv extra --within group --subject ID --json");
  EXPECT_EQ(w["V"].get<double>(), 0.0);
  EXPECT_TRUE(relativelyNear(w["p"].get<double>(), 0.00909069801592506, 1e-10));
  const auto m = runJson("stats mannwhitney " + data("sleep.csv") + " --dv extra --between group --json");
  EXPECT_EQ(m["W"].get<double>(), 25.5);
  EXPECT_TRUE(relativelyNear(m["p"].get<double>(), 0.0693275754336266, 1e-10));
  const auto f = runJson("stats friedman " + data("rm_oneway.csv") + " --dv score --within condition --subject subject --json");
  EXPECT_TRUE(relativelyNear(f["chisq"].get<double>(), 21.6, 1e-13));
  EXPECT_EQ(f["df"].get<double>(), 3.0);
  EXPECT_TRUE(relativelyNear(f["p"].get<double>(), 7.90046165867983e-05, 1e-10));
}

TEST(Cli, ReadableTextWithoutJson) {
  const RunResult r = runTlab("stats anova " + data("rm_oneway.csv") + " --dv score --within condition --subject subject");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.output.find("condition"), std::string::npos);
  EXPECT_NE(r.output.find("Mauchly"), std::string::npos);
}

TEST(Cli, ErrorsAreOneLineWithExitCodeOne) {
  const RunResult missing = runTlab("stats ttest " + data("sleep.csv") + " --dv speed --between group", true);
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.output.find("tlab: error:"), std::string::npos);
  EXPECT_NE(missing.output.find("no column 'speed'"), std::string::npos);
  const std::string bad = std::filesystem::temp_directory_path() / "tlab_cli_bad.csv";
  std::ofstream(bad) << "g,y\na,1\na,2\nb,oops\nb,4\n";
  const RunResult nonNumeric = runTlab("stats ttest " + bad + " --dv y --between g", true);
  EXPECT_EQ(nonNumeric.exitCode, 1);
  EXPECT_NE(nonNumeric.output.find(bad + ":4"), std::string::npos) << nonNumeric.output;
  const RunResult oneLevel = runTlab("stats mannwhitney " + data("sleep.csv") + " --dv extra --between ID", true);
  EXPECT_EQ(oneLevel.exitCode, 1);
  EXPECT_NE(oneLevel.output.find("needs exactly 2"), std::string::npos) << oneLevel.output;
}

TEST(Cli, ReportWritesHtmlAndMarkdownWithFigures) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tlab_cli_report";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const RunResult r = runTlab("report " + data("mixed.csv") + " --dv y --between g --within time --subject s -o " +
                                  (dir / "r.html").string() + " --markdown " + (dir / "r.md").string(),
                              true);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream html(dir / "r.html");
  const std::string page((std::istreambuf_iterator<char>(html)), std::istreambuf_iterator<char>());
  EXPECT_NE(page.find("data:image/svg+xml;base64,"), std::string::npos);
  EXPECT_NE(page.find("78.37"), std::string::npos);  // time F (car::Anova type II: 78.3713124889596)
  EXPECT_TRUE(std::filesystem::exists(dir / "r.md"));
  EXPECT_TRUE(std::filesystem::exists(dir / "r_fig1.svg"));
  EXPECT_TRUE(std::filesystem::exists(dir / "r_fig2.svg"));
}

TEST(Cli, ReproduceAndStatcheck) {
  const auto carnecky = runJson("reproduce carnecky --json");
  ASSERT_EQ(carnecky["rows"].size(), 3u);
  for (const auto& row : carnecky["rows"]) {
    EXPECT_TRUE(row["checks"][0]["consistent"].get<bool>());   // Welch
    EXPECT_FALSE(row["checks"][1]["consistent"].get<bool>());  // Student
    EXPECT_FALSE(row["checks"][2]["consistent"].get<bool>());  // paired
  }
  const auto elmqvist = runJson("reproduce elmqvist --json");
  EXPECT_EQ(elmqvist["f_tests"].size(), 9u);
  EXPECT_EQ(elmqvist["design_count"], 192);
  const std::string seed = std::string(TLAB_SOURCE_DIR) + "/../shared/seeds/004_5a2d71233f7987a3.txt";
  if (!std::filesystem::exists(seed)) GTEST_SKIP() << "seed papers not found";
  const auto check = runJson("statcheck " + seed + " --json");
  EXPECT_EQ(check["summary"]["results"], 5);
  EXPECT_EQ(check["summary"]["errors"], 0);
}

// statcheck end to end: a folder with text, HTML and PDF, every output form and statcheck's options.
TEST(Cli, StatcheckFolderJsonCsvAndOptions) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tlab_cli_statcheck";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "sub");
  std::ofstream(dir / "sub" / "one.txt") << "A one-tailed test: t(28) = 2.20, p = .018; and p = .2 alone.";
  std::filesystem::copy_file(data("statcheck_sample.html"), dir / "paper.html");
  std::filesystem::copy_file(data("statcheck_sample.pdf"), dir / "paper.pdf");
  const auto all = runJson("statcheck " + dir.string() + " --json");
  ASSERT_EQ(all.size(), 3u);  // paper.html, paper.pdf, sub/one.txt
  EXPECT_EQ(all[0]["summary"]["results"], 4);
  EXPECT_EQ(all[1]["summary"]["decision_errors"], 1);
  const auto& one = all[2];
  EXPECT_EQ(one["results"][0]["test_type"], "t");
  EXPECT_TRUE(one["results"][0]["df1"].is_null());
  EXPECT_EQ(one["results"][0]["df2"], 28.0);
  EXPECT_EQ(one["results"][0]["error"], true);  // two-tailed p = .036 by default, as statcheck
  EXPECT_EQ(one["summary"]["apa_factor"], 0.5);
  EXPECT_EQ(one["summary"]["one_tailed_in_txt"], true);
  const auto detected = runJson("statcheck " + (dir / "sub" / "one.txt").string() + " --json --one-tailed-text");
  EXPECT_EQ(detected["results"][0]["error"], false);
  EXPECT_EQ(detected["results"][0]["one_tailed"], true);
  const RunResult csv = runTlab("statcheck " + dir.string() + " --csv");
  EXPECT_EQ(csv.exitCode, 0);
  EXPECT_EQ(csv.output.rfind("source,test_type,df1,df2,test_comp,test_value,p_comp,reported_p,computed_p,raw,error,", 0), 0u);
  EXPECT_EQ(std::count(csv.output.begin(), csv.output.end(), '\n'), 1 + 4 + 4 + 1);
  const RunResult pvalues = runTlab("statcheck " + (dir / "sub" / "one.txt").string() + " --csv --all-p-values");
  EXPECT_NE(pvalues.output.find(",\"=\",0.2,1,"), std::string::npos) << pvalues.output;
  const RunResult missing = runTlab("statcheck " + (dir / "nothing.txt").string(), true);
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.output.find("nothing.txt: no such file or folder"), std::string::npos) << missing.output;
  std::filesystem::remove_all(dir);
}

// reproduce --table: Carnecky's Table 1 as CSV gives the conclusion of `reproduce carnecky`.
TEST(Cli, ReproduceTableGeneralisesCarnecky) {
  const auto rows = runJson("reproduce --table " + data("carnecky_table1.csv") + " --json")["rows"];
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& row : rows) EXPECT_EQ(row["consistent_with"], nlohmann::json::array({"welch"}));
  const std::filesystem::path bad = std::filesystem::temp_directory_path() / "tlab_cli_bad_table.csv";
  std::ofstream(bad) << "mean1,sd1,n1,mean2,sd2,n2,t\n1.5,0.5,20,1.2,0.4,20,2.1\n1.5,abc,20,1.2,0.4,20,2.1\n";
  const RunResult r = runTlab("reproduce --table " + bad.string(), true);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.output.find("tlab_cli_bad_table.csv:3: column 'sd1'"), std::string::npos) << r.output;
  std::filesystem::remove(bad);
}

}  // namespace
}  // namespace tlab::analysis
