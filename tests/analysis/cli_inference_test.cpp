// End-to-end: `tlab stats mixed`, `stats pairwise` and `stats ttest --bayes` as a user runs them,
// on the reference data of reference/mixed_models.R; the expected numbers are R's (lme4 1.1-31,
// lmerTest 3.1-3, pairwise.t.test, BayesFactor 0.9.12-4.4) from reference/mixed/expected.csv.
#include <nlohmann/json.hpp>

#include <string>

#include "tests/analysis/mixed_reference.hpp"
#include "tests/analysis/test_support.hpp"
#include "tests/support/run_command.hpp"

namespace tlab::analysis {
namespace {

using testing::MixedReference;
using testing::referencePath;
using testing::relativelyNear;

tlab::testing::CommandResult runTlab(const std::string& arguments) {
  return tlab::testing::runCommand(std::string(TLAB_EXE) + " " + arguments);
}

nlohmann::json runJson(const std::string& arguments) {
  const auto r = runTlab(arguments);
  EXPECT_EQ(r.exitCode, 0) << arguments << "\n" << r.err;
  return nlohmann::json::parse(r.out);
}

const MixedReference& reference() {
  static const MixedReference r;
  return r;
}

TEST(CliMixed, LinearMixedModelJsonEqualsLmer) {
  const auto j = runJson("stats mixed " + referencePath("slopes.csv") +
                         " --formula \"time ~ method * alpha + (1 + method | participant) + (1 | stimulus)\" --factor alpha --json");
  EXPECT_EQ(j["family"], "gaussian");
  EXPECT_EQ(j["method"], "REML");
  EXPECT_EQ(j["observations"], 640);
  ASSERT_EQ(j["fixed_effects"].size(), 4u);
  for (const auto& e : j["fixed_effects"]) {
    const std::string term = e["term"];
    EXPECT_TRUE(relativelyNear(e["estimate"].get<double>(), reference().at("slopes", "fixed", term, "estimate"), 1e-6)) << term;
    EXPECT_TRUE(relativelyNear(e["std_error"].get<double>(), reference().at("slopes", "fixed", term, "std_error"), 1e-6)) << term;
    EXPECT_TRUE(relativelyNear(e["df"].get<double>(), reference().at("slopes", "fixed", term, "df"), 1e-4)) << term;
    for (const char* key : {"statistic", "p"}) EXPECT_TRUE(e.contains(key));
  }
  bool correlation = false;
  for (const auto& v : j["random_effects"])
    if (v.contains("term2")) {
      correlation = true;
      EXPECT_EQ(v["group"], "participant");
      EXPECT_TRUE(relativelyNear(v["correlation"].get<double>(),
                                 reference().at("slopes", "random", "participant|(Intercept)|methodsmart", "sd_cor"), 1e-5));
    }
  EXPECT_TRUE(correlation);
  EXPECT_TRUE(relativelyNear(j["reml_criterion"].get<double>(), reference().at("slopes", "fit", "", "reml_criterion"), 1e-9));
  EXPECT_TRUE(relativelyNear(j["aic"].get<double>(), reference().at("slopes", "fit", "", "aic"), 1e-9));
  EXPECT_TRUE(j["warnings"].empty());
}

TEST(CliMixed, LogisticMixedModelAndLevelsOption) {
  // --levels makes "smart" the reference: the intercept becomes R's (Intercept) + methodsmart.
  const std::string formula = " --formula \"correct ~ method + (1 | participant) + (1 | stimulus)\" --family binomial";
  const auto j = runJson("stats mixed " + referencePath("binary_crossed.csv") + formula + " --json");
  EXPECT_EQ(j["method"], "Laplace");
  EXPECT_FALSE(j.contains("reml_criterion"));
  EXPECT_FALSE(j["fixed_effects"][0].contains("df"));
  EXPECT_TRUE(relativelyNear(j["fixed_effects"][2]["estimate"].get<double>(),
                             reference().at("binary_crossed", "fixed", "methodsmart", "estimate"), 1e-4));
  EXPECT_TRUE(relativelyNear(j["log_likelihood"].get<double>(), reference().at("binary_crossed", "fit", "", "log_likelihood"), 1e-8));
  const auto releveled = runJson("stats mixed " + referencePath("binary_crossed.csv") + formula + " --levels method=smart,alpha,halo --json");
  EXPECT_EQ(releveled["fixed_effects"][1]["term"], "methodalpha");
  EXPECT_TRUE(relativelyNear(releveled["fixed_effects"][0]["estimate"].get<double>(),
                             reference().at("binary_crossed", "fixed", "(Intercept)", "estimate") +
                                 reference().at("binary_crossed", "fixed", "methodsmart", "estimate"),
                             1e-4));
  const auto text = runTlab("stats mixed " + referencePath("binary_crossed.csv") + formula);
  EXPECT_EQ(text.exitCode, 0);
  EXPECT_NE(text.out.find("Laplace approximation"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("methodsmart"), std::string::npos);
}

TEST(CliMixed, ErrorsNameTheProblem) {
  const auto bad = runTlab("stats mixed " + referencePath("crossed.csv") + " --formula \"rt ~ method\"");
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.err.find("no random-effects term"), std::string::npos) << bad.err;
  const auto notBinary =
      runTlab("stats mixed " + referencePath("crossed.csv") + " --formula \"rt ~ method + (1|participant)\" --family binomial");
  EXPECT_EQ(notBinary.exitCode, 1);
  EXPECT_NE(notBinary.err.find("must be 0 or 1"), std::string::npos) << notBinary.err;
}

TEST(CliPairwise, HolmAdjustedPairedTestsEqualR) {
  const auto j = runJson("stats pairwise " + referencePath("crossed.csv") + " --dv rt --within method --subject participant --json");
  EXPECT_EQ(j["adjust"], "holm");
  ASSERT_EQ(j["comparisons"].size(), 3u);
  for (const auto& c : j["comparisons"]) {
    std::string key = c["first"].get<std::string>() + "|" + c["second"].get<std::string>();
    if (!reference().has("pairwise_within", "holm", key, "p")) key = c["second"].get<std::string>() + "|" + c["first"].get<std::string>();
    EXPECT_EQ(c["test"], "paired t");
    EXPECT_TRUE(relativelyNear(c["p"].get<double>(), reference().at("pairwise_within", "holm", key, "p"), 1e-10));
    EXPECT_TRUE(relativelyNear(c["p_adjusted"].get<double>(), reference().at("pairwise_within", "holm", key, "p_adjusted"), 1e-10));
  }
  const auto none = runJson("stats pairwise " + std::string(TLAB_TEST_DATA) + "/analysis/plant_growth.csv --dv weight --between group "
                            "--adjust none --json");
  EXPECT_EQ(none["comparisons"][0]["p"], none["comparisons"][0]["p_adjusted"]);
  const auto bad = runTlab("stats pairwise " + referencePath("crossed.csv") + " --dv rt --within method --subject participant "
                           "--adjust tukey");
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.err.find("'tukey' is not a p-value adjustment"), std::string::npos) << bad.err;
}

TEST(CliBayes, TTestBayesFactorEqualsTtestBF) {
  const std::string sleep = std::string(TLAB_TEST_DATA) + "/analysis/sleep.csv";
  const auto paired = runJson("stats ttest " + sleep + " --dv extra --within group --subject ID --bayes --json");
  EXPECT_TRUE(relativelyNear(paired["bf10"].get<double>(), reference().at("bayes", "paired", "medium", "bf10"), 1e-6));
  const auto wide = runJson("stats ttest " + sleep + " --dv extra --between group --bayes --rscale 1.4142135623730951 --json");
  EXPECT_TRUE(relativelyNear(wide["bf10"].get<double>(), reference().at("bayes", "two_sample", "ultrawide", "bf10"), 1e-6));
  const auto text = runTlab("stats ttest " + sleep + " --dv extra --within group --subject ID --bayes");
  EXPECT_NE(text.out.find("BF10 = "), std::string::npos) << text.out;
}

}  // namespace
}  // namespace tlab::analysis
