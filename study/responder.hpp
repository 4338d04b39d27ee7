#pragma once
// Responder: who answers the trials — the participant at the window (WindowResponder) or a
// SimulatedObserver. The TrialRunner owns the order, the time limits and the database; a
// responder only shows screens and returns answers with their monotonic timestamps.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "study/experiment.hpp"
#include "study/session_plan.hpp"
#include "study/stimulus_library.hpp"

namespace tlab::study {

struct TrialView {
  const PlannedTrial& plan;
  const PreparedTrial& prepared;
  double limitSeconds = 120.0;  // for this question: its own limit or what is left of the trial's
  int index = 1;                // 1-based position in the session
  int total = 1;
  // Called once when the stimulus is first on screen (monotonic ns, detail JSON): the runner
  // commits the onset at once, so the log knows every stimulus a participant saw.
  std::function<void(std::int64_t, const std::string&)> onset;
};

struct Response {
  std::optional<std::string> text;  // nullopt: no answer within the limit
  std::optional<double> rtSeconds;  // onset → response (nullopt when missing)
  std::int64_t onsetNs = 0;         // monotonic clock at the stimulus onset (buffer swap)
  std::int64_t responseNs = 0;      // monotonic clock at the response (or the time-out)
  std::string note;
};

// A timestamped event the responder saw (pause, resume, key, layout), stored in the events table.
struct ResponderEvent {
  std::int64_t tNs = 0;
  std::string kind;
  std::string detail;
};

class Responder {
 public:
  virtual ~Responder() = default;
  virtual std::string mode() const = 0;  // "window" or "simulated"
  // A text screen (welcome, task instructions, goodbye). False: the session was closed.
  virtual bool showMessage(const std::string& title, const std::string& text) = 0;
  // nullopt: the session was closed before an answer (the trial stays unanswered).
  virtual std::optional<Response> respond(const TrialView& view) = 0;
  // One value 1..points per item; nullopt: the session was closed.
  virtual std::optional<std::vector<int>> answerQuestionnaire(const Questionnaire& questionnaire) = 0;
  // Events gathered since the last call (the runner stores them).
  virtual std::vector<ResponderEvent> takeEvents() { return {}; }
};

}  // namespace tlab::study
