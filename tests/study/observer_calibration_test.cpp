// The simulated observer's closed-form prediction and its calibration to published results
// (`tlab simulate --calibrate`, issue 15 part 7). Expected values: closed forms of the model in
// study/simulate/observer_prediction.hpp; Carnecky Table 1 for the built-in published results.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "analysis/summary_likelihood.hpp"
#include "study/simulate/observer_calibration.hpp"
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
      {"low", questions(2, 10, 0.3, 0.25)}, {"mid", questions(2, 10, 0.55, 0.25)}, {"high", questions(2, 10, 0.9, 0.25)}};
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
  EXPECT_NE(r.out.find("published mean  fitted mean  mean before"), std::string::npos) << r.out;
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

TEST(ObserverPrediction, AgreesWithSimulatingTheObserver) {
  // 40 simulated participants of the tiny experiment: the observed mean proportion correct per
  // method lies within 0.08 (about 2.5 standard errors) of the closed-form prediction that
  // --calibrate prints as "mean before" (at the experiment's parameters). Seeded, so the numbers
  // are the same on every run (observed 0.650 / 0.781, predicted 0.660 / 0.827 when written).
  const auto dir = freshDir("prediction_vs_simulation");
  const std::string db = (dir / "s.db").string();
  ASSERT_EQ(runCommand(kTlab + " simulate " + studyData("tiny.toml") + " --participants 40 --db " + db).exitCode, 0);
  ASSERT_EQ(runCommand(kTlab + " export " + db + " --csv " + (dir / "csv").string()).exitCode, 0);
  const auto rows = parseCsv(readText((dir / "csv" / "trials.csv").string()));
  const auto column = [&](const std::string& name) { return std::size_t(std::find(rows[0].begin(), rows[0].end(), name) - rows[0].begin()); };
  std::map<std::string, std::map<std::string, std::pair<double, int>>> perParticipant;  // method → participant → (correct, n)
  for (std::size_t r = 1; r < rows.size(); ++r) {
    if (rows[r][column("phase")] != "test") continue;
    auto& cell = perParticipant[rows[r][column("method")]][rows[r][column("participant")]];
    cell.first += std::stod(rows[r][column("correct")]);
    cell.second += 1;
  }
  const std::string csv = (dir / "published.csv").string();
  std::ofstream(csv) << "factor,level,n,mean,variance\nmethod,alpha,40,0.5,0.04\nmethod,smart,40,0.5,0.04\n";
  const auto fit = runCommand(kTlab + " simulate " + studyData("tiny.toml") + " --calibrate " + csv + " --participants 40");
  ASSERT_EQ(fit.exitCode, 0) << fit.err;
  for (const std::string method : {"alpha", "smart"}) {
    double observed = 0.0;
    for (const auto& [participant, cell] : perParticipant[method]) observed += cell.first / cell.second / 40.0;
    std::istringstream line(fit.out.substr(fit.out.find("\n  " + method + " ")));
    std::string level, n, published, fitted, before;
    line >> level >> n >> published >> fitted >> before;
    EXPECT_NEAR(observed, std::stod(before), 0.08) << method;
  }
}

TEST(ObserverCalibration, ObserverTableIsCheckedLikeEveryOtherKey) {
  const auto dir = freshDir("observer_table");
  const std::string base = readText(studyData("tiny.toml"));
  const auto design = [&](const std::string& table) {
    const std::string path = (dir / "e.toml").string();
    std::ofstream(path) << base << "\n[observer]\n" << table << "\n";
    return runCommand(kTlab + " design " + path);
  };
  const int line = int(std::count(base.begin(), base.end(), '\n')) + 3;  // the line after [observer]
  const auto range = design("sensitivity = -1");
  EXPECT_EQ(range.exitCode, 1);
  EXPECT_NE(range.err.find("e.toml:" + std::to_string(line) + ": observer.sensitivity: must be within [0, 100]"), std::string::npos)
      << range.err;
  const auto typo = design("sensitivty = 1");
  EXPECT_EQ(typo.exitCode, 1);
  EXPECT_NE(typo.err.find("observer.sensitivty: unknown key"), std::string::npos) << typo.err;
  EXPECT_EQ(design("sensitivity = 7.5\nthreshold = 0.9").exitCode, 0);
}
