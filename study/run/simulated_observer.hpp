#pragma once
// SimulatedObserver: a participant model for pilots, tests and power analysis. Its accuracy and
// response time depend on what the rendered stimulus shows at the question's points.
//
// Per question (parameters in ObserverParams, [observer] in the experiment file):
//   c   = mean local RMS luminance contrast at the marked points (targets for search tasks), over
//         a 9×9 window of the unmarked rendering (study/run/image_contrast.hpp)
//   v   = min(1, c / contrast_reference) · (1 − layer_penalty·(layers in front))₊
//         (layers in front: the answer form's layersInFront — layer-index, gauge figure on layer k)
//   s   = participant skill, exp(skill_spread · z_participant), fixed per participant
//   p_k = 1 / (1 + exp(−sensitivity · (s·v − threshold)))  — the observer *knows* the answer
//   with probability give_up_share: no answer (missing); else with probability lapse or 1 − p_k:
//   a guess (uniform over the answer's alternatives; counts and floor points: noisy estimates;
//   gauge figure: a direction uniform over the hemisphere facing the viewer), otherwise the true
//   answer (floor points within a quarter of the correct distance; a gauge figure's normal tilted
//   by a Gaussian angle of sd gauge_degrees · (1 + gauge_growth · (1 − v))). The answer's form
//   (tasks/answer_form.hpp: guess, known) does this per answer kind.
//   RT  = (base_seconds + slow_seconds · (1 − v)) / √s · exp(rt_sigma · z); past the question's
//         limit the answer is missing (Carnecky Sec. 8: missing = wrong).
// All randomness comes from SeededRandom streams seeded by (experiment seed, participant, trial
// sequence), so a resumed simulated session answers exactly as an uninterrupted one.
#include <cstdint>
#include <string>

#include "study/design/experiment.hpp"
#include "study/run/responder.hpp"

namespace tlab::study {

struct ObserverDecision {
  double visibility = 0.0;
  double pKnow = 0.0;
  bool knows = false;
  bool gaveUp = false;
  double seconds = 0.0;
  std::optional<std::string> answer;  // nullopt: no answer within the limit
  std::string typed;                  // what the observer would answer given time (the autopilot types it)
};

// What a simulated observer does, in words and with these parameters' values: the text the
// report of simulated data, `tlab simulate --help` and the README give.
std::string describeSimulatedObserver(const ObserverParams& params);

class SimulatedObserver final : public Responder {
 public:
  SimulatedObserver(ObserverParams params, std::uint64_t experimentSeed, const std::string& participant,
                    double paceSeconds = 0.0);
  std::string mode() const override { return "simulated"; }
  bool showMessage(const std::string&, const std::string&) override { return true; }
  // Consents, answers forms with seeded valid values, takes breaks of their minimum length.
  std::optional<bool> askConsent(const std::string&, const ConsentSpec&) override { return true; }
  std::optional<std::vector<std::string>> fillForm(const std::string& title, const std::vector<FormField>& fields) override;
  std::optional<Response> respond(const TrialView& view) override;
  bool showFeedback(const TrialView&, const Feedback&) override { return true; }
  bool takeBreak(const BreakSpec& spec) override;
  std::vector<ResponderEvent> takeEvents() override;
  // The headless GL that rendered what the observer sees, recorded with its session (no window).
  void setRenderer(std::optional<DisplayInfo> renderer) { renderer_ = std::move(renderer); }
  std::optional<DisplayInfo> display() const override { return renderer_; }

  double skill() const { return skill_; }
  // The model's decision for one question (pure given the seed).
  ObserverDecision decide(const TrialView& view) const;
  double visibility(const PreparedTrial& prepared) const;

 private:
  ObserverParams params_;
  std::uint64_t seed_;
  double skill_;
  double paceSeconds_;  // real seconds slept per simulated second (0: as fast as possible)
  std::int64_t clockNs_ = 0;
  int questionnaires_ = 0;
  std::vector<ResponderEvent> events_;
  std::optional<DisplayInfo> renderer_;
};

}  // namespace tlab::study
