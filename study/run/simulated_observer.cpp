#include "study/run/simulated_observer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "core/seeded_random.hpp"
#include "study/run/image_contrast.hpp"
#include "study/design/order_permutations.hpp"

namespace tlab::study {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Standard normal deviate (Box-Muller) from the portable uniform source.
double normal(core::SeededRandom& random) {
  const double u1 = (double(random.uniform()) + 0x1p-25);
  const double u2 = double(random.uniform());
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}

std::string formatNumber(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

std::vector<std::string> labelsWithRole(const tasks::Question& q, const std::string& role) {
  std::vector<std::string> out;
  for (const auto& p : q.points)
    if (p.role == role) out.push_back(p.label);
  return out;
}

std::string guess(const tasks::Question& q, core::SeededRandom& random) {
  using tasks::AnswerKind;
  switch (q.answerKind) {
    case AnswerKind::LayerNumber: {
      const auto truth = std::get<std::int64_t>(q.truth);
      return std::to_string(1 + random.below(std::uint32_t(std::max<std::int64_t>(truth + 1, 3))));
    }
    case AnswerKind::Label: {
      auto labels = labelsWithRole(q, "candidate");
      if (labels.empty()) labels = q.labels();
      return labels[random.below(std::uint32_t(labels.size()))];
    }
    case AnswerKind::LabelSet: {
      std::string text;
      for (const auto& l : labelsWithRole(q, "mark"))
        if (random.below(2)) text += (text.empty() ? "" : ",") + l;
      return text.empty() ? "none" : text;
    }
    case AnswerKind::Count: {
      const double truth = double(std::get<std::int64_t>(q.truth));
      const double estimate = truth + normal(random) * std::max(1.0, 0.3 * truth);
      return std::to_string(std::max<std::int64_t>(0, std::llround(estimate)));
    }
    case AnswerKind::Letter: {
      static const char* letters[] = {"C", "K", "R", "X", "Y"};
      return letters[random.below(5)];
    }
    case AnswerKind::FloorPoint: {
      const glm::dvec2 truth = std::get<glm::dvec2>(q.truth);
      const double spread = std::max(1.0, 4.0 * q.correctWithin);
      return formatNumber(truth.x + normal(random) * spread) + "," + formatNumber(truth.y + normal(random) * spread);
    }
  }
  return "";
}

std::string trueAnswer(const tasks::Question& q, core::SeededRandom& random) {
  using tasks::AnswerKind;
  switch (q.answerKind) {
    case AnswerKind::LayerNumber:
    case AnswerKind::Count: return std::to_string(std::get<std::int64_t>(q.truth));
    case AnswerKind::Label:
    case AnswerKind::Letter: return std::get<std::string>(q.truth);
    case AnswerKind::LabelSet: {
      std::string text;
      for (const auto& l : std::get<std::set<std::string>>(q.truth)) text += (text.empty() ? "" : ",") + l;
      return text.empty() ? "none" : text;
    }
    case AnswerKind::FloorPoint: {
      const glm::dvec2 truth = std::get<glm::dvec2>(q.truth);
      const double spread = 0.25 * q.correctWithin;
      return formatNumber(truth.x + normal(random) * spread) + "," + formatNumber(truth.y + normal(random) * spread);
    }
  }
  return "";
}

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
         ") (layer-index questions: times 1 - " + g(p.layerPenalty) + " per layer behind the first), and "
         "knows the answer with probability 1 / (1 + exp(-" + g(p.sensitivity) + " (s v - " + g(p.threshold) +
         "))), where s is the participant's skill (log-normal, sd of log " + g(p.skillSpread) +
         "). An observer who knows answers the ground truth; otherwise, and in a share " + g(p.lapse) +
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
  if (q.answerKind == tasks::AnswerKind::LayerNumber)
    v *= std::max(0.0, 1.0 - params_.layerPenalty * double(std::get<std::int64_t>(q.truth) - 1));
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
  const std::string answer = d.knows ? trueAnswer(view.prepared.question, random) : guess(view.prepared.question, random);
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
