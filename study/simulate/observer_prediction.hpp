#pragma once
// ObserverPrediction: what the simulated observer (simulated_observer.hpp) predicts, in closed
// form, for the proportion of correct answers per participant in one condition — its mean and its
// variance over participants. This is the model side of `tlab simulate --calibrate`.
//
// For a participant of skill s = exp(skill_spread · x), x ~ N(0, 1) (integrated by Gauss-Hermite
// quadrature), question t with visibility v_t and guess success g_t is answered correctly with
//   p_t(s) = a_t(s) · [k_t + (1 − k_t) g_t],   k_t = (1 − lapse) / (1 + exp(−sensitivity (s v_t − threshold)))
// where a_t(s), the probability that an answer is given in time, is (1 − give_up)^q · P(T_q ≤ L)
// for the q-th question of a trial with a time limit L (T_q: the sum of the q response times,
// log-normal each, their sum approximated by a log-normal of the same mean and variance —
// Fenton 1960), or (1 − give_up) · P(rt_t ≤ L_t) with a per-question limit only (a give-up uses the
// rest of the trial's time, as the observer does). The participant's proportion correct P(s) is the
// mean of p_t over their questions; over participants and skills
//   mean = E[P],  variance = Var[P] + E[Σ p_t (1 − p_t)] / T²   (binomial noise within a participant).
#include <optional>
#include <vector>

#include "study/design/experiment.hpp"

namespace tlab::study {

struct PredictionQuestion {
  int participant = 0;  // the slot that answers it
  int trial = 0;        // questions of one trial (same participant) share its time limit
  int order = 1;        // 1-based position within the trial
  double visibility = 0.0;
  double guessCorrect = 0.0;  // probability that a guess is scored correct
  double questionLimitSeconds = 120.0;
  std::optional<double> trialLimitSeconds;
};

struct PredictedProportion {
  double mean = 0.0;
  double variance = 0.0;
  int participants = 0;
};

PredictedProportion predictProportionCorrect(const ObserverParams& params, const std::vector<PredictionQuestion>& questions);

}  // namespace tlab::study
