#include "study/simulate/observer_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <tuple>

#include "analysis/csv_reader.hpp"
#include "analysis/nelder_mead.hpp"
#include "analysis/reproduce_carnecky.hpp"
#include "analysis/summary_likelihood.hpp"
#include "study/design/counterbalancing.hpp"
#include "study/design/session_plan.hpp"
#include "study/run/simulated_observer.hpp"
#include "tasks/task_registry.hpp"

namespace tlab::study {

namespace {

constexpr int kGuesses = 24;

double logistic(double u) { return 1.0 / (1.0 + std::exp(-u)); }
double logit(double p) { return std::log(p / (1.0 - p)); }

// The fitted parameters on unbounded scales, mapped into the ranges [observer] accepts:
// sensitivity in (0, 100), threshold in (0, 1), skill_spread in (0, 3).
ObserverParams withFitted(ObserverParams p, const std::vector<double>& u) {
  p.sensitivity = 100.0 * logistic(u[0]);
  p.threshold = logistic(u[1]);
  p.skillSpread = 3.0 * logistic(u[2]);
  return p;
}

std::vector<double> fitted(const ObserverParams& p) {
  const auto inside = [](double x) { return std::clamp(x, 1e-4, 1.0 - 1e-4); };
  return {logit(inside(p.sensitivity / 100.0)), logit(inside(p.threshold)), logit(inside(p.skillSpread / 3.0))};
}

// Probability that a guess at this question is scored correct: kGuesses seeded guesses.
double guessSuccess(const PlannedTrial& plan, const PreparedTrial& prepared, const ObserverParams& params, std::uint64_t seed) {
  ObserverParams guessing = params;
  guessing.lapse = 1.0;  // always guess
  guessing.giveUpShare = 0.0;
  const auto task = tasks::makeTask(plan.task);
  int correct = 0;
  for (int g = 0; g < kGuesses; ++g) {
    const SimulatedObserver observer(guessing, seed, "calibration-guess-" + std::to_string(g));
    const ObserverDecision d = observer.decide({plan, prepared, 1e12, plan.sequence, 1, {}});
    try {
      correct += task->score(prepared.question, tasks::Answer{d.answer, 1.0}).correct ? 1 : 0;
    } catch (const std::invalid_argument&) {  // a malformed guess scores nothing
    }
  }
  return double(correct) / kGuesses;
}

}  // namespace

PublishedResults carneckyPublishedResults() {
  const std::map<std::string, std::string> levels = {
      {"Normal Variation", "normal-variation"}, {"Alpha Blending", "alpha"}, {"Illustrative Transparency", "smart"}};
  PublishedResults r{"Carnecky et al. 2013, Table 1 (proportion correct per method, n = 36)", "method", {}};
  std::set<std::string> seen;
  for (const auto& c : analysis::carneckyTable1()) {
    for (const auto& [label, mean, variance] : {std::tuple{c.first, c.mean1, c.variance1}, {c.second, c.mean2, c.variance2}})
      if (seen.insert(label).second) r.conditions.push_back({levels.at(label), c.n, mean.value, variance.value});
  }
  return r;
}

PublishedResults readPublishedResults(const std::string& path) {
  const analysis::Table t = analysis::readCsvFile(path);
  PublishedResults r{path, "", {}};
  const std::size_t factor = t.columnIndex("factor"), level = t.columnIndex("level"), n = t.columnIndex("n"),
                    mean = t.columnIndex("mean"), variance = t.columnIndex("variance");
  for (std::size_t row = 0; row < t.rowCount(); ++row) {
    const auto fail = [&](const std::string& column, const std::string& message) {
      throw std::invalid_argument(t.where(row) + ": " + column + ": " + message);
    };
    if (r.factor.empty()) r.factor = t.text(row, factor);
    if (t.text(row, factor) != r.factor) fail("factor", "'" + t.text(row, factor) + "': one factor per file (the first row names '" + r.factor + "')");
    const double count = t.number(row, n), m = t.number(row, mean), v = t.number(row, variance);
    if (count < 2 || count != std::floor(count)) fail("n", "must be a whole number >= 2");
    if (m < 0 || m > 1) fail("mean", "a proportion correct must lie in [0, 1]");
    if (v < 0 || v > 0.25) fail("variance", "the variance of a proportion lies in [0, 0.25]");
    r.conditions.push_back({t.text(row, level), std::size_t(count), m, v});
  }
  if (r.conditions.empty()) throw std::invalid_argument(path + ": no published conditions (columns factor, level, n, mean, variance)");
  return r;
}

std::map<std::string, std::vector<PredictionQuestion>> predictionQuestions(const Experiment& experiment, StimulusLibrary& stimuli,
                                                                          const std::string& factor, int participants) {
  if (!experiment.factor(factor)) throw std::invalid_argument(experiment.path + ": no factor '" + factor + "' to calibrate against");
  const Design design = makeDesign(experiment);
  std::map<std::string, std::vector<PredictionQuestion>> out;
  for (int slot = 0; slot < participants; ++slot) {
    const SimulatedObserver observer(experiment.observer, experiment.seed, "calibration");
    std::map<std::string, int> trials;
    for (const PlannedTrial& plan : makeSessionPlan(experiment, design, slot).trials) {
      if (plan.phase != Phase::Test) continue;
      const PreparedTrial prepared = stimuli.prepare(plan);
      PredictionQuestion q;
      q.participant = slot;
      q.trial = trials.emplace(std::to_string(plan.block) + "/" + plan.taskId + "/" + std::to_string(plan.trial), int(trials.size())).first->second;
      q.order = plan.question;
      q.visibility = observer.visibility(prepared);
      q.guessCorrect = guessSuccess(plan, prepared, experiment.observer, experiment.seed);
      q.questionLimitSeconds = plan.timeLimitSeconds;
      q.trialLimitSeconds = plan.trialTimeLimitSeconds;
      out[plan.levels.at(factor)].push_back(q);
    }
  }
  return out;
}

CalibrationFit calibrateObserver(const ObserverParams& start, const std::map<std::string, std::vector<PredictionQuestion>>& questions,
                                 const PublishedResults& published) {
  for (const auto& c : published.conditions)
    if (!questions.count(c.level) || questions.at(c.level).empty())
      throw std::invalid_argument(published.source + ": level '" + c.level + "' of factor '" + published.factor +
                                  "' has no test questions in the experiment");
  const auto logLikelihood = [&](const ObserverParams& p) {
    double sum = 0.0;
    for (const auto& c : published.conditions) {
      const PredictedProportion pred = predictProportionCorrect(p, questions.at(c.level));
      sum += analysis::summaryLogLikelihood(c.n, c.mean, c.variance, pred.mean, pred.variance);
    }
    return sum;
  };
  CalibrationFit fit;
  fit.start = start;
  fit.startLogLikelihood = logLikelihood(start);
  // Nelder-Mead from the experiment's parameters and from a 3×3×3 grid over the ranges (the
  // likelihood has flat regions where the logistic saturates), each restarted twice to refresh a
  // collapsed simplex (Lagarias et al. 1998); the best end point wins.
  std::vector<std::vector<double>> starts = {fitted(start)};
  for (const double sensitivity : {2.0, 8.0, 30.0})
    for (const double threshold : {0.2, 0.5, 0.8})
      for (const double spread : {0.1, 0.5, 1.5}) {
        ObserverParams p = start;
        p.sensitivity = sensitivity;
        p.threshold = threshold;
        p.skillSpread = spread;
        starts.push_back(fitted(p));
      }
  analysis::NelderMeadOptions options;
  options.initialStep = {1.0, 1.0, 1.0};
  std::vector<double> u;
  double best = INFINITY;
  for (const auto& s0 : starts) {
    analysis::NelderMeadResult r{s0, 0.0, 0, false};
    for (int restart = 0; restart < 3; ++restart) {
      r = analysis::nelderMeadMinimize([&](const std::vector<double>& x) { return -logLikelihood(withFitted(start, x)); }, r.x, options);
      fit.evaluations += r.evaluations;
    }
    if (r.value < best) {
      best = r.value;
      u = r.x;
      fit.converged = r.converged;
    }
  }
  fit.params = withFitted(start, u);
  fit.logLikelihood = logLikelihood(fit.params);
  for (const auto& [name, value, high] : {std::tuple{"sensitivity", fit.params.sensitivity, 100.0},
                                          {"threshold", fit.params.threshold, 1.0}, {"skill_spread", fit.params.skillSpread, 3.0}})
    if (value < 1e-3 * high || value > (1.0 - 1e-3) * high)
      fit.notes.push_back(std::string(name) + " ended at the edge of its range [0, " + std::to_string(int(high)) +
                          "]: inside it the model cannot come closer to the published results (see the table); "
                          "treat this fit as a sign that the observer model does not describe these data");
  for (const auto& c : published.conditions)
    fit.rows.push_back({c, predictProportionCorrect(start, questions.at(c.level)), predictProportionCorrect(fit.params, questions.at(c.level))});
  return fit;
}

std::string observerToml(const ObserverParams& p) {
  char text[640];
  std::snprintf(text, sizeof text,
                "[observer]\ncontrast_reference = %.6g\nsensitivity = %.6g\nthreshold = %.6g\nskill_spread = %.6g\nlapse = %.6g\n"
                "layer_penalty = %.6g\nbase_seconds = %.6g\nslow_seconds = %.6g\nrt_sigma = %.6g\ngive_up_share = %.6g\n",
                p.contrastReference, p.sensitivity, p.threshold, p.skillSpread, p.lapse, p.layerPenalty, p.baseSeconds,
                p.slowSeconds, p.rtSigma, p.giveUpShare);
  return text;
}

}  // namespace tlab::study
