// The simulated observer's closed-form prediction and its calibration to published results
// (`tlab simulate --calibrate`, issue 15 part 7). Expected values: closed forms of the model in
// study/observer_prediction.hpp; Carnecky Table 1 for the built-in published results.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "analysis/summary_likelihood.hpp"
#include "study/observer_calibration.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;
using namespace tlab::study;

namespace {

const std::string kTlab = TLAB_EXE;

ObserverParams plainObserver() {
  ObserverParams p;
  p.skillSpread = 0.0;
  p.lapse = 0.0;
  p.giveUpShare = 0.0;
  p.rtSigma = 0.0;
  return p;
}

std::vector<PredictionQuestion> questions(int participants, int perParticipant, double visibility, double guess) {
  std::vector<PredictionQuestion> out;
  for (int j = 0; j < participants; ++j)
    for (int q = 1; q <= perParticipant; ++q) out.push_back({j, q, 1, visibility, guess, 120.0, std::nullopt});
  return out;
}

}  // namespace

TEST(ObserverPrediction, KnowOrGuessWithoutSkillSpreadIsBinomial) {
  // p = k + (1 - k) g with k = 1/(1 + exp(-4 (0.5 - 0.35))); per participant the proportion of 10
  // questions has variance p (1 - p) / 10.
  const double k = 1.0 / (1.0 + std::exp(-4.0 * (0.5 - 0.35)));
  const double p = k + (1.0 - k) * 0.25;
  const PredictedProportion r = predictProportionCorrect(plainObserver(), questions(6, 10, 0.5, 0.25));
  EXPECT_EQ(r.participants, 6);
  EXPECT_NEAR(r.mean, p, 1e-12);
  EXPECT_NEAR(r.variance, p * (1.0 - p) / 10.0, 1e-12);
}

TEST(ObserverPrediction, TrialTimeLimitCutsLaterQuestionsAndSkillSpreadAddsVariance) {
  // Deterministic 6 s answers (v = 1, slow_seconds irrelevant) in a 20 s trial: questions 1-3 fit,
  // question 4 does not, so the mean is 3/4 of the per-question p.
  ObserverParams o = plainObserver();
  o.baseSeconds = 6.0;
  std::vector<PredictionQuestion> qs;
  for (int q = 1; q <= 4; ++q) qs.push_back({0, 0, q, 1.0, 0.0, 120.0, 20.0});
  const double k = 1.0 / (1.0 + std::exp(-4.0 * (1.0 - 0.35)));
  EXPECT_NEAR(predictProportionCorrect(o, qs).mean, 0.75 * k, 1e-12);
  // Skill spread: the between-participant variance adds to the binomial part.
  ObserverParams spread = plainObserver();
  spread.skillSpread = 0.5;
  const auto many = questions(4, 10, 0.4, 0.2);
  EXPECT_GT(predictProportionCorrect(spread, many).variance, predictProportionCorrect(plainObserver(), many).variance);
}

TEST(ObserverCalibration, RecoversTheResultsItWasGiven) {
  // Published results made by the model itself at known parameters: the fit reproduces them and
  // its likelihood is at least that of the true parameters.
  ObserverParams truth;
  truth.sensitivity = 7.0;
  truth.threshold = 0.5;
  truth.skillSpread = 0.4;
  const std::map<std::string, std::vector<PredictionQuestion>> qs = {
      {"low", questions(12, 20, 0.3, 0.25)}, {"mid", questions(12, 20, 0.55, 0.25)}, {"high", questions(12, 20, 0.9, 0.25)}};
  PublishedResults published{"made up", "method", {}};
  for (const auto& [level, q] : qs) {
    const PredictedProportion p = predictProportionCorrect(truth, q);
    published.conditions.push_back({level, 36, p.mean, p.variance});
  }
  const CalibrationFit fit = calibrateObserver(ObserverParams{}, qs, published);
  ASSERT_EQ(fit.rows.size(), 3u);
  for (const auto& row : fit.rows) {
    EXPECT_NEAR(row.predicted.mean, row.published.mean, 2e-3) << row.published.level;
    EXPECT_NEAR(row.predicted.variance, row.published.variance, 2e-3) << row.published.level;
  }
  double truthLogLikelihood = 0.0;
  for (const auto& row : fit.rows)
    truthLogLikelihood += tlab::analysis::summaryLogLikelihood(36, row.published.mean, row.published.variance, row.published.mean,
                                                               row.published.variance);
  EXPECT_GE(fit.logLikelihood, truthLogLikelihood - 1e-6);
  EXPECT_GT(fit.logLikelihood, fit.startLogLikelihood);
  EXPECT_THROW(calibrateObserver(ObserverParams{}, {{"low", qs.at("low")}}, published), std::invalid_argument);
}

TEST(ObserverCalibration, PublishedResultsFromCarneckyAndFromFiles) {
  const PublishedResults c = carneckyPublishedResults();
  EXPECT_EQ(c.factor, "method");
  ASSERT_EQ(c.conditions.size(), 3u);
  EXPECT_EQ(c.conditions[0].level, "normal-variation");
  EXPECT_DOUBLE_EQ(c.conditions[0].mean, 0.234);
  EXPECT_DOUBLE_EQ(c.conditions[2].variance, 0.077);  // Illustrative Transparency
  EXPECT_EQ(c.conditions[2].n, 36u);
  const auto dir = freshDir("published_results");
  const std::string path = (dir / "p.csv").string();
  std::ofstream(path) << "factor,level,n,mean,variance\nmethod,alpha,20,0.4,0.03\nmethod,smart,20,1.4,0.03\n";
  try {
    readPublishedResults(path);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), path + ":3: mean: a proportion correct must lie in [0, 1]");
  }
}

TEST(ObserverCalibration, SimulateCalibrateFitsPrintsAndPastes) {
  const auto dir = freshDir("calibrate_cli");
  const std::string csv = (dir / "published.csv").string();
  std::ofstream(csv) << "factor,level,n,mean,variance\nmethod,alpha,24,0.45,0.04\nmethod,smart,24,0.6,0.05\n";
  const auto r = runCommand(kTlab + " simulate " + studyData("tiny.toml") + " --calibrate " + csv);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("published mean"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("log-likelihood"), std::string::npos);
  const std::size_t table = r.out.find("\n[observer]\n");
  ASSERT_NE(table, std::string::npos) << r.out;
  // The fitted table is accepted by the experiment file parser.
  std::string experiment = readText(studyData("tiny.toml"));
  experiment += "\n" + r.out.substr(table);
  const std::string fitted = (dir / "fitted.toml").string();
  std::ofstream(fitted) << experiment;
  const auto design = runCommand(kTlab + " design " + fitted);
  EXPECT_EQ(design.exitCode, 0) << design.err;
  // Carnecky's methods are not all in the tiny experiment: one clear line.
  const auto carnecky = runCommand(kTlab + " simulate " + studyData("tiny.toml") + " --calibrate carnecky");
  EXPECT_EQ(carnecky.exitCode, 1);
  EXPECT_NE(carnecky.err.find("level 'normal-variation' of factor 'method' has no test questions"), std::string::npos) << carnecky.err;
}
