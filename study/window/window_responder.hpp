#pragma once
// WindowResponder: the participant at a GLFW window. Screens are drawn into a Canvas (text with
// TextPainter) and shown with WindowContext::present. A trial shows the marked stimulus, the
// question, a countdown and the answer band; answers are given by clicking a label (Label: one
// click answers; LabelSet: clicks toggle, Enter submits), clicking a letter button (C K R X Y), or
// typing (numbers, labels, "x,z" floor points) and pressing Enter. An answer that does not parse
// is not submitted: the error is shown and the clock keeps running.
//
// Timing: the stimulus onset is the monotonic time (steady_clock) right after the buffer swap
// of the first frame showing the stimulus; input events are timestamped in the GLFW callbacks,
// which run inside glfwWaitEventsTimeout as soon as the event arrives. Escape pauses (the paused
// time is left out of the RT and the countdown); closing the window ends the session cleanly.
#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/gpu/window_context.hpp"
#include "study/run/responder.hpp"
#include "study/window/screen_layout.hpp"
#include "study/run/text_painter.hpp"

namespace tlab::study {

struct FrameTiming {
  int frames = 0;
  double presentMeanMs = 0.0;  // present(): upload + blit + swap, per frame
  double presentMaxMs = 0.0;
  int onsets = 0;
  double onsetMeanMs = 0.0;    // first stimulus frame: start of present() → swap returned
  double onsetMaxMs = 0.0;
  double clockResolutionNs = 0.0;    // smallest positive step of steady_clock observed
  double eventWaitMaxMs = 0.0;       // longest wait in the event loop while a trial ran (bounds RT resolution when idle)
};

class SimulatedObserver;
class TrialScreen;

class WindowResponder final : public Responder {
 public:
  WindowResponder(gpu::WindowContext& window, TextPainter& painter);
  // Autopilot (jsPsych's "visual" simulation): every screen is shown and answered through the
  // real input handling, with the keys and clicks a simulated observer would give; `pace` scales
  // its response times to real time.
  void engageAutopilot(std::shared_ptr<SimulatedObserver> observer, double pace);
  ~WindowResponder() override;

  std::string mode() const override { return autopilot_ ? "autopilot" : "window"; }
  bool showMessage(const std::string& title, const std::string& text) override;
  std::optional<bool> askConsent(const std::string& title, const ConsentSpec& consent) override;      // window_screens.cpp
  std::optional<std::vector<std::string>> fillForm(const std::string& title, const std::vector<FormField>& fields) override;
  std::optional<Response> respond(const TrialView& view) override;
  bool showFeedback(const TrialView& view, const Feedback& feedback) override;
  bool takeBreak(const BreakSpec& spec) override;
  std::vector<ResponderEvent> takeEvents() override;
  std::optional<DisplayInfo> display() const override;

  FrameTiming timing() const;

  // Input as the GLFW callbacks deliver it (public for the static callbacks).
  struct Input {
    enum class Kind { Key, Char, Click, Drag, Move, Close } kind = Kind::Key;
    int key = 0;
    char32_t codepoint = 0;
    double x = 0, y = 0;  // click/cursor position in canvas pixels (Drag: the motion dx, dy)
    std::int64_t tNs = 0;
  };
  void push(Input input) { inputs_.push_back(input); }
  glm::dvec2 cursorToCanvas(double x, double y) const;
  // Drag tracking for the static callbacks: press starts, motion reports deltas, release ends.
  void pressAt(glm::dvec2 p);
  void release();
  std::optional<glm::dvec2> dragTo(glm::dvec2 p);

 private:
  struct TrialInput {
    std::optional<std::string> answer;
    bool closed = false;
    std::int64_t pausedNs = 0;
  };
  TrialInput trialInput(TrialScreen& screen, const Input& in);
  // respond()'s steps (window_trial.cpp).
  struct TrialClock;
  void showOnset(const TrialView& view, TrialScreen& screen, const Canvas& current, TrialClock& clock);
  bool takeTrialInputs(const TrialView& view, TrialScreen& screen, TrialClock& clock, int& shownSecond,
                       std::optional<Response>& ended);
  void presentFrame(TrialScreen& screen, const Canvas& current, TrialClock& clock);
  void logLiveFrame(TrialScreen& screen, std::int64_t swapNs);
  std::optional<Input> nextInput(const Canvas& screen);
  std::optional<std::string> askField(const std::string& title, const FormField& field, int index, int count);
  int refreshHz() const;
  // Autopilot: inputs due at a time, released by waitForInput as if the participant gave them.
  void script(std::vector<Input> inputs, double afterSeconds);
  void scriptText(const std::string& text, bool enter, double afterSeconds);
  std::int64_t present(const Canvas& canvas);  // returns the monotonic time after the swap
  bool pause();
  void waitForInput(double seconds, bool inTrial = false);
  Canvas blank() const;
  void event(std::int64_t tNs, const std::string& kind, const std::string& detail);

  gpu::WindowContext& window_;
  TextPainter& painter_;
  std::deque<Input> inputs_;
  std::shared_ptr<SimulatedObserver> autopilot_;
  double autopilotPace_ = 0.05;
  std::deque<std::pair<std::int64_t, Input>> script_;
  int feedbacks_ = 0, breaks_ = 0;  // fault points
  std::vector<ResponderEvent> events_;
  bool closed_ = false;
  std::optional<glm::dvec2> dragFrom_;
  // timing statistics
  int frames_ = 0;
  double presentSumMs_ = 0.0, presentMaxMs_ = 0.0;
  int onsets_ = 0;
  double onsetSumMs_ = 0.0, onsetMaxMs_ = 0.0;
  double lastPresentMs_ = 0.0;
  double lastPresentOnsetMs_ = 0.0;  // the current trial's stimulus request → swap
  double eventWaitMaxMs_ = 0.0;
};

// The participant's window (OpenGL 4.5 core); without a display, one line that says how to run the
// session (a display, xvfb-run) or to pilot it without a window (tlab simulate).
std::unique_ptr<gpu::WindowContext> openParticipantWindow(int width, int height, const std::string& title);

// Switches the window to full screen on the primary monitor; throws when there is none.
void makeFullscreen(gpu::WindowContext& window);

}  // namespace tlab::study
