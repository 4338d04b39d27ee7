#pragma once
// ObserverCalibration: fits the simulated observer's parameters to published results by maximum
// likelihood (`tlab simulate --calibrate carnecky|FILE.csv`), so that a pilot or power analysis
// starts from accuracies observed in people rather than from the defaults.
//
// Published results: per level of one factor, n participants and the mean and variance over them
// of the per-participant proportion correct (Carnecky Table 1: method, n = 36). The experiment's
// test questions of `participants` slots are prepared (rendered) once; each gives its visibility
// and the probability that a guess scores (24 seeded guesses, scored by the task). The fitted
// parameters are sensitivity, threshold and skill_spread (the others stay as in [observer]); the
// log-likelihood is analysis::summaryLogLikelihood of every published condition under
// predictProportionCorrect (observer_prediction.hpp), maximised by Nelder-Mead from the
// experiment's parameters and a grid of starts. A parameter that ends at the edge of its range is
// reported as a note: the model does not describe the data well there.
#include <map>
#include <string>
#include <vector>

#include "study/design/experiment.hpp"
#include "study/simulate/observer_prediction.hpp"
#include "study/run/stimulus_library.hpp"

namespace tlab::study {

struct PublishedCondition {
  std::string level;
  std::size_t n = 0;
  double mean = 0.0;      // of the per-participant proportion correct
  double variance = 0.0;  // over participants
};

struct PublishedResults {
  std::string source;  // "Carnecky et al. 2013, Table 1" or the file
  std::string factor;
  std::vector<PublishedCondition> conditions;
};

// Carnecky Table 1 (analysis::carneckyTable1), its methods named as examples/carnecky2013.toml does.
PublishedResults carneckyPublishedResults();
// A CSV file with the columns factor, level, n, mean, variance (one factor; proportions in [0, 1]).
PublishedResults readPublishedResults(const std::string& path);

// The experiment's test questions per level of `factor`, as the model sees them.
std::map<std::string, std::vector<PredictionQuestion>> predictionQuestions(const Experiment& experiment,
                                                                          StimulusLibrary& stimuli,
                                                                          const std::string& factor, int participants);

struct CalibrationRow {
  PublishedCondition published;
  PredictedProportion atStart;    // at the experiment's [observer] parameters
  PredictedProportion predicted;  // at the fitted parameters
};

struct CalibrationFit {
  ObserverParams start, params;
  double startLogLikelihood = 0.0, logLikelihood = 0.0;
  int evaluations = 0;
  bool converged = false;
  std::vector<CalibrationRow> rows;
  std::vector<std::string> notes;  // e.g. a parameter at the edge of its range
};

// Throws std::invalid_argument when a published level has no questions in the experiment.
CalibrationFit calibrateObserver(const ObserverParams& start,
                                 const std::map<std::string, std::vector<PredictionQuestion>>& questions,
                                 const PublishedResults& published);

// The [observer] table of the fit, to paste into the experiment file.
std::string observerToml(const ObserverParams& params);

}  // namespace tlab::study
