#pragma once
// Responder: who answers the trials — the participant at the window (WindowResponder) or a
// SimulatedObserver. The TrialRunner owns the order, the time limits and the database; a
// responder only shows screens and returns answers with their monotonic timestamps.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "study/design/experiment.hpp"
#include "study/design/session_plan.hpp"
#include "study/run/stimulus_library.hpp"
#include "study/store/store.hpp"

namespace tlab::study {

struct TrialView {
  const PlannedTrial& plan;
  const PreparedTrial& prepared;
  double limitSeconds = 120.0;  // for this question: its own limit or what is left of the trial's
  int index = 1;                // 1-based position in the session
  int total = 1;
  // Called once when the stimulus is first on screen (monotonic ns, detail JSON): the runner
  // commits the onset at once, so the log knows every stimulus a participant saw.
  std::function<void(std::int64_t, const std::string&)> onset{};
};

// After a training answer: whether it was right and the right answer in words.
struct Feedback {
  bool correct = false;
  std::string rightAnswer;
  std::optional<std::string> given;  // the participant's answer as stored (nullopt: none in time)
};

// The display a window session runs on (stored with the session as JSON).
struct DisplayInfo {
  std::string glBackend;  // "glfw" for a window; the headless backend (egl/osmesa) that rendered a simulated session's stimuli
  std::string glVendor, glRenderer, glVersion;
  int windowWidth = 0, windowHeight = 0, framebufferWidth = 0, framebufferHeight = 0;
  int refreshHz = 0;     // the monitor's, as GLFW reports it (0: unknown)
  int swapInterval = 1;
  std::string browserJson{};  // browser sessions: screen, window, device pixel ratio, refresh estimate, pixels per cm
  std::string json() const;
};

struct Response {
  std::optional<std::string> text;  // nullopt: no answer within the limit
  std::optional<double> rtSeconds;  // onset → response (nullopt when missing)
  std::int64_t onsetNs = 0;         // monotonic clock at the stimulus onset (buffer swap)
  std::int64_t responseNs = 0;      // monotonic clock at the response (or the time-out)
  std::string note;
  std::optional<double> onsetFrameMs;   // window: swap-to-swap interval of the onset frame
  std::optional<int> lateFrames;        // window: frames over 1.5 refresh intervals during the trial
  std::optional<double> onsetToSwapMs;  // window: stimulus frame requested → swap returned
};

// A timestamped event the responder saw (pause, resume, key, layout), stored in the events table.
using ResponderEvent = EventRecord;  // stored as they came (study/store/store.hpp)

// The monotonic clock in nanoseconds: the clock of every stored onset and response.
std::int64_t monotonicNs();

// Every front end walks the same session flow (TrialRunner) through these calls; each returns
// nullopt/false when the participant closed the session.
class Responder {
 public:
  virtual ~Responder() = default;
  virtual std::string mode() const = 0;  // "window", "autopilot" or "simulated"
  // A text screen (welcome, task instructions, "training is over", debrief). False: closed.
  virtual bool showMessage(const std::string& title, const std::string& text) = 0;
  // The consent screen: true accepted, false declined.
  virtual std::optional<bool> askConsent(const std::string& title, const ConsentSpec& consent) = 0;
  // One answer per field, each accepted by fieldError (study/design/form_field.hpp), after the
  // participant confirmed them (participant information and questionnaires).
  virtual std::optional<std::vector<std::string>> fillForm(const std::string& title, const std::vector<FormField>& fields) = 0;
  // nullopt: the session was closed before an answer (the trial stays unanswered).
  virtual std::optional<Response> respond(const TrialView& view) = 0;
  // The last screen (the debrief with its completion code): a message the participant closes, or
  // for a browser the page that stays (study/serve/browser_responder.hpp).
  virtual void showDebrief(const std::string& title, const DebriefSpec& debrief) {
    showMessage(title, debrief.text + (debrief.completionCode.empty() ? "" : "\n\n" + texts().text("end.completion_code") + " " + debrief.completionCode));
  }
  // After a training answer: the stimulus with the right answer drawn, and whether it was right.
  virtual bool showFeedback(const TrialView& view, const Feedback& feedback) = 0;
  // A pause of at least spec.minSeconds; returns when the participant continues.
  virtual bool takeBreak(const BreakSpec& spec) = 0;
  // Events gathered since the last call (the runner stores them).
  virtual std::vector<ResponderEvent> takeEvents() { return {}; }
  // The display the session runs on; nullopt for simulated observers.
  virtual std::optional<DisplayInfo> display() const { return std::nullopt; }
  // The words of every screen (TrialRunner::run gives the experiment's before the first screen).
  void useTexts(const ParticipantTexts& texts) { texts_ = texts; }
  const ParticipantTexts& texts() const { return texts_; }

 private:
  ParticipantTexts texts_;
};

}  // namespace tlab::study
