// WindowResponder's trials: respond() — the onset, the frame record, the countdown — and the
// inputs of a trial. The window, its callbacks and plain messages: window_responder.cpp; forms,
// consent, feedback and breaks: window_screens.cpp.
#include <algorithm>
#include <cmath>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

#include "study/window/trial_screen.hpp"
#include "study/window/window_responder.hpp"
#include "study/window/window_style.hpp"
#include "study/run/session_wording.hpp"
#include "study/run/simulated_observer.hpp"
#include "tasks/answer_form.hpp"
#include "tasks/answer_parser.hpp"

namespace tlab::study {

// One input of a trial, handled by the screen (answers, selections, camera moves) or here (pause,
// close). `answer` is the text it submits, if any.
WindowResponder::TrialInput WindowResponder::trialInput(TrialScreen& screen, const Input& in) {
  TrialInput r;
  const bool arrow = in.key == GLFW_KEY_UP || in.key == GLFW_KEY_DOWN || in.key == GLFW_KEY_LEFT || in.key == GLFW_KEY_RIGHT;
  switch (in.kind) {
    case Input::Kind::Close:
      closed_ = true;
      event(in.tNs, "close", "");
      r.closed = true;
      break;
    case Input::Kind::Key:
      if (arrow && screen.takesArrows()) {
        screen.arrow(in.key == GLFW_KEY_UP ? 1 : in.key == GLFW_KEY_DOWN ? -1 : 0, in.key == GLFW_KEY_RIGHT ? 1 : in.key == GLFW_KEY_LEFT ? -1 : 0);
        event(in.tNs, "camera", screen.cameraText());
      } else if (in.key == GLFW_KEY_ESCAPE) {
        const std::int64_t start = monotonicNs();
        r.closed = !pause();
        r.pausedNs = monotonicNs() - start;
      } else if (in.key == GLFW_KEY_BACKSPACE) {
        screen.backspace();
      } else if (in.key == GLFW_KEY_ENTER || in.key == GLFW_KEY_KP_ENTER) {
        r.answer = screen.enter();
      }
      break;
    case Input::Kind::Char: r.answer = screen.typedChar(utf8(in.codepoint)); break;
    case Input::Kind::Click: r.answer = screen.click(in.x, in.y); break;
    case Input::Kind::Move: screen.moveTo(in.x, in.y); break;
    case Input::Kind::Drag:
      if (screen.takesArrows()) {
        screen.drag(in.x, in.y);
        event(in.tNs, "camera", screen.cameraText());
      }
      break;
  }
  return r;
}

// The clock of one trial: onset, paused time and the frame record since the onset.
struct WindowResponder::TrialClock {
  double refreshMs = 1000.0 / 60;
  std::int64_t onsetNs = 0, pausedNs = 0, lastSwapNs = 0;
  std::optional<double> onsetFrameMs;
  int lateFrames = 0;

  double elapsed(std::int64_t t) const { return (t - onsetNs - pausedNs) / 1e9; }
  Response response(std::optional<std::string> text, std::int64_t t, std::string note, double onsetToSwapMs) const {
    Response r;
    r.text = std::move(text);
    r.onsetNs = onsetNs;
    r.responseNs = t;
    if (r.text) r.rtSeconds = std::max(0.0, elapsed(t));
    r.note = std::move(note);
    r.onsetFrameMs = onsetFrameMs;
    r.lateFrames = lateFrames;
    r.onsetToSwapMs = onsetToSwapMs;
    return r;
  }
};

// The first stimulus frame: its swap is the onset, committed at once through view.onset (or kept
// as an event); the autopilot's answer is scheduled from it.
void WindowResponder::showOnset(const TrialView& view, TrialScreen& screen, const Canvas& current, TrialClock& clock) {
  const tasks::Question& q = view.prepared.question;
  const std::int64_t before = monotonicNs();
  clock.onsetNs = clock.lastSwapNs = present(current);
  lastPresentOnsetMs_ = (clock.onsetNs - before) / 1e6;
  if (autopilot_) {
    const ObserverDecision d = autopilot_->decide(view);
    scriptText(d.typed, tasks::answerForm(q).widget(q).buttons.empty(), std::min(d.seconds * autopilotPace_, view.limitSeconds / 2));
  }
  ++onsets_;
  onsetSumMs_ += lastPresentOnsetMs_;
  onsetMaxMs_ = std::max(onsetMaxMs_, lastPresentOnsetMs_);
  nlohmann::json layout = screen.layoutJson();
  layout["present_ms"] = lastPresentOnsetMs_;
  if (view.onset) view.onset(clock.onsetNs, layout.dump());  // committed now, before any answer
  else event(clock.onsetNs, "onset", layout.dump());
}

// The inputs that have arrived. True when the trial is over: `ended` holds the parsed answer's
// response, or nothing when the window was closed.
bool WindowResponder::takeTrialInputs(const TrialView& view, TrialScreen& screen, TrialClock& clock, int& shownSecond,
                                      std::optional<Response>& ended) {
  while (!inputs_.empty()) {
    const Input in = inputs_.front();
    inputs_.pop_front();
    const TrialInput r = trialInput(screen, in);
    if (r.closed) return true;
    clock.pausedNs += r.pausedNs;
    if (r.pausedNs > 0) shownSecond = -1;  // the pause screen covered the trial: draw it again
    if (!r.answer) continue;
    try {
      tasks::parseAnswer(view.prepared.question, *r.answer);
      ended = clock.response(r.answer, in.tNs, "", lastPresentOnsetMs_);
      return true;
    } catch (const tasks::AnswerFormatError& e) {
      screen.rejected(refusalWording(e, texts()));  // not submitted: the clock keeps running
      event(in.tNs, "invalid-answer", *r.answer);
    }
  }
  return false;
}

// Presents the current frame, recording the first frame's interval and frames over 1.5 refresh
// intervals (late); a new picture of a live view is logged as a "frame" event at its swap.
void WindowResponder::presentFrame(TrialScreen& screen, const Canvas& current, TrialClock& clock) {
  const std::int64_t swap = present(current);
  const double interval = (swap - clock.lastSwapNs) / 1e6;
  if (clock.lastSwapNs == clock.onsetNs && !clock.onsetFrameMs) clock.onsetFrameMs = interval;
  if (interval > 1.5 * clock.refreshMs) ++clock.lateFrames;
  clock.lastSwapNs = swap;
  logLiveFrame(screen, swap);
}

void WindowResponder::logLiveFrame(TrialScreen& screen, std::int64_t swapNs) {
  if (const auto shown = screen.shownLiveFrame(swapNs)) event(swapNs, kFrameEvent, frameJson(*shown));
}

// The stimulus is on screen from the swap after its first frame (the onset, committed at once
// through view.onset); then frames are presented at the refresh rate (PsychoPy's frame record:
// every swap interval is known, and frames over 1.5 refresh intervals count as late) until an
// answer parses or the limit passes. Paused time is left out of the RT and the countdown. A
// frame is drawn only when it is due, so every picture a live view renders is shown and logged
// (its renderer's state across frames replays exactly).
std::optional<Response> WindowResponder::respond(const TrialView& view) {
  if (closed_) return std::nullopt;
  TrialScreen screen(view, blank(), painter_, texts());
  inputs_.clear();
  TrialClock clock;
  clock.refreshMs = 1000.0 / (refreshHz() > 0 ? refreshHz() : 60);
  Canvas current = screen.frame(view.limitSeconds);
  showOnset(view, screen, current, clock);
  logLiveFrame(screen, clock.onsetNs);
  int shownSecond = -1;
  while (true) {
    const double left = view.limitSeconds - clock.elapsed(monotonicNs());
    if (left <= 0) {
      event(monotonicNs(), "timeout", "");
      return clock.response(std::nullopt, monotonicNs(), "time limit", lastPresentOnsetMs_);
    }
    waitForInput(std::min(0.005, left), true);
    std::optional<Response> ended;
    if (takeTrialInputs(view, screen, clock, shownSecond, ended)) return ended;
    if ((monotonicNs() - clock.lastSwapNs) / 1e6 < clock.refreshMs) continue;  // not due yet
    const int second = int(std::ceil(view.limitSeconds - clock.elapsed(monotonicNs())));
    if (screen.dirty() || second != shownSecond) {
      current = screen.frame(view.limitSeconds - clock.elapsed(monotonicNs()));
      shownSecond = second;
    }
    presentFrame(screen, current, clock);
  }
}

}  // namespace tlab::study
