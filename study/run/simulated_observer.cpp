#include "study/run/simulated_observer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "core/seeded_random.hpp"
#include "tasks/answer_form.hpp"
#include "study/run/image_contrast.hpp"
#include "study/design/order_permutations.hpp"

namespace tlab::study {

namespace {

double normal(core::SeededRandom& random) { return tasks::standardNormal(random); }
std::string formatNumber(double v) { return tasks::answerNumber(v); }

}  // namespace

std::string describeSimulatedObserver(const ObserverParams& p) {
  const auto g = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return std::string(buf);
  };
  return "A simulated observer does not look at the picture as a person does. For each question it "
         "measures the local RMS luminance contrast c in a 9x9-pixel window at the question's marked probe "
         "points of the rendered stimulus, takes the visibility v = min(1, c / " + g(p.contrastReference) +
         ") (questions about a layer behind the first: times 1 - " + g(p.layerPenalty) + " per layer in front), and "
         "knows the answer with probability 1 / (1 + exp(-" + g(p.sensitivity) + " (s v - " + g(p.threshold) +
         "))), where s is the participant's skill (log-normal, sd of log " + g(p.skillSpread) +
         "). An observer who knows answers the ground truth (a gauge figure's normal tilted by a random angle of sd " +
         g(p.gaugeDegrees) + " (1 + " + g(p.gaugeGrowth) + " (1 - v)) degrees); otherwise, and in a share " + g(p.lapse) +
         " of questions (lapses), it guesses uniformly among the possible answers; in a share " +
         g(p.giveUpShare) + " it gives no answer. Its response time is (" + g(p.baseSeconds) + " + " +
         g(p.slowSeconds) + " (1 - v)) / sqrt(s) seconds times a log-normal factor (sd " + g(p.rtSigma) +
         "). Differences between conditions therefore follow from this contrast heuristic at the probes, "
         "not from perceiving shape; the parameters are the experiment file's [observer] table "
         "(tlab simulate --calibrate fits them to published results).";
}

SimulatedObserver::SimulatedObserver(ObserverParams params, std::uint64_t experimentSeed, const std::string& participant,
                                     double paceSeconds)
    : params_(params), seed_(mixSeed(experimentSeed, "observer:" + participant)), paceSeconds_(paceSeconds) {
  core::SeededRandom random(mixSeed(seed_, "skill"));
  skill_ = std::exp(params_.skillSpread * normal(random));
}

double SimulatedObserver::visibility(const PreparedTrial& prepared) const {
  const tasks::Question& q = prepared.question;
  double sum = 0.0;
  int n = 0;
  for (const auto& p : q.points) {
    sum += localRmsContrast(*prepared.picture, p.pixel, 4);
    ++n;
  }
  double v = n ? std::min(1.0, sum / n / params_.contrastReference) : 0.0;
  v *= std::max(0.0, 1.0 - params_.layerPenalty * double(tasks::answerForm(q).layersInFront(q)));
  return v;
}

ObserverDecision SimulatedObserver::decide(const TrialView& view) const {
  core::SeededRandom random(mixSeed(seed_, std::uint64_t(view.plan.sequence)));
  ObserverDecision d;
  d.visibility = visibility(view.prepared);
  d.pKnow = 1.0 / (1.0 + std::exp(-params_.sensitivity * (skill_ * d.visibility - params_.threshold)));
  d.gaveUp = random.uniform() < params_.giveUpShare;
  const bool lapse = random.uniform() < params_.lapse;
  d.knows = !lapse && random.uniform() < d.pKnow;
  const double median = (params_.baseSeconds + params_.slowSeconds * (1.0 - d.visibility)) / std::sqrt(skill_);
  d.seconds = median * std::exp(params_.rtSigma * normal(random));
  const tasks::Question& q = view.prepared.question;
  const tasks::AnswerForm& form = tasks::answerForm(q);
  const std::string answer = d.knows ? form.known(q, random, d.visibility, {params_.gaugeDegrees, params_.gaugeGrowth}) : form.guess(q, random);
  d.typed = answer;
  if (!d.gaveUp && d.seconds <= view.limitSeconds) d.answer = answer;
  return d;
}

std::optional<Response> SimulatedObserver::respond(const TrialView& view) {
  const ObserverDecision d = decide(view);
  Response r;
  const double seconds = d.answer ? d.seconds : view.limitSeconds;
  r.onsetNs = clockNs_;
  if (view.onset) view.onset(r.onsetNs, "{\"simulated\":true}");
  clockNs_ += std::int64_t(seconds * 1e9);
  r.responseNs = clockNs_;
  r.text = d.answer;
  if (d.answer) r.rtSeconds = seconds;
  r.note = d.answer ? "" : (d.gaveUp ? "simulated: no answer" : "simulated: time limit");
  if (paceSeconds_ > 0.0) std::this_thread::sleep_for(std::chrono::duration<double>(seconds * paceSeconds_));
  return r;
}

std::optional<std::vector<std::string>> SimulatedObserver::fillForm(const std::string& title, const std::vector<FormField>& fields) {
  core::SeededRandom random(mixSeed(seed_, "form:" + title + ":" + std::to_string(questionnaires_++)));
  std::vector<std::string> values;
  for (const auto& f : fields) {
    switch (f.kind) {
      case FieldKind::Likert: values.push_back(std::to_string(1 + int(random.below(std::uint32_t(f.points))))); break;
      case FieldKind::Choice: values.push_back(f.options[random.below(std::uint32_t(f.options.size()))]); break;
      case FieldKind::Number: {
        const double v = f.minimum + (std::min(f.maximum, f.minimum + 100.0) - f.minimum) * double(random.uniform());
        values.push_back(f.integer ? std::to_string(static_cast<long long>(std::floor(v))) : formatNumber(v));
        break;
      }
      case FieldKind::Text: values.push_back("simulated answer " + std::to_string(random.below(1000))); break;
    }
  }
  return values;
}

bool SimulatedObserver::takeBreak(const BreakSpec& spec) {
  events_.push_back({clockNs_, "break", "{\"min_seconds\":" + formatNumber(spec.minSeconds) + "}"});
  clockNs_ += std::int64_t(spec.minSeconds * 1e9);
  events_.push_back({clockNs_, "break-end", "{\"seconds\":" + formatNumber(spec.minSeconds) + "}"});
  return true;
}

std::vector<ResponderEvent> SimulatedObserver::takeEvents() {
  std::vector<ResponderEvent> out;
  out.swap(events_);
  return out;
}

}  // namespace tlab::study
