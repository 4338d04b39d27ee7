#pragma once
// TrialScreen: what a trial looks like in the participant's window and what each input means —
// the layout (question, counter, stimulus at a whole-number scale, the floor plan beside it for
// floor-point answers, the answer band with letter buttons), the marks that can be clicked, the
// typed text, the selected labels, the gauge figure, the live view of interactive trials, and one
// handler per kind of input that returns the answer it gives, if any. What is drawn follows the
// question's widget (tasks/answer_form.hpp): the window draws widget primitives, not tasks. No clock, no GL, no database: the window
// responder owns timing, pausing and submitting.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/run/canvas.hpp"
#include "study/run/frame_log.hpp"
#include "study/run/live_view.hpp"
#include "study/run/responder.hpp"
#include "study/window/answer_band.hpp"
#include "study/window/screen_layout.hpp"
#include "study/run/text_painter.hpp"
#include "tasks/answer_form.hpp"

namespace tlab::study {

class TrialScreen {
 public:
  TrialScreen(const TrialView& view, Canvas blank, TextPainter& painter, const ParticipantTexts& texts);

  // The frame to show with `secondsLeft` on the countdown (the live view drawn in when there is one).
  Canvas frame(double secondsLeft);
  // Where everything is (stimulus, canvas, labels, buttons, plan), stored with the onset event.
  const nlohmann::json& layoutJson() const { return layoutJson_; }
  bool live() const { return live_.has_value(); }
  // Arrow keys and drags turn something: the live view's camera, or the gauge figure.
  bool takesArrows() const;

  // Inputs; each returns the answer text it submits, if any, and marks the screen for redrawing.
  std::optional<std::string> typedChar(const std::string& utf8Char);
  std::optional<std::string> enter();  // typed text, or the selected labels ("none" when none)
  void backspace();
  std::optional<std::string> click(double x, double y);
  void arrow(int forward, int right);      // live trials: walk or zoom; gauge: slant and tilt
  void drag(double dx, double dy);         // live trials: orbit or look around; gauge: the stick follows
  void moveTo(double x, double y);         // live trials: the dynamic lens follows the cursor
  // An answer that does not parse: shown in red, the typed text cleared.
  void rejected(const std::string& error);

  bool dirty() const { return dirty_; }
  // Live trials, after each buffer swap at `shownNs`: the live view's picture as a LiveFrame when
  // it is a new one (numbered from 0 in this trial, with the inputs that moved the view since the
  // last frame shown, "start" for the first, and the SHA-256 of its pixels); nothing otherwise.
  std::optional<LiveFrame> shownLiveFrame(std::int64_t shownNs);
  // The camera of a live trial (or the gauge's orientation) after a move, for the event log.
  std::string cameraText() const;

 private:
  std::optional<std::string> clickLabel(double x, double y);
  std::optional<std::string> clickFloorPlan(double x, double y) const;
  std::string selectedText() const;
  double gaugeRadius() const;  // in screen pixels
  // Lines from the answer band's row at `top`, at the band's left margin.
  void drawLines(Canvas& c, const std::vector<std::string>& lines, int top, float pixels, Rgba color);

  const TrialView& view_;
  const tasks::AnswerForm& form_;
  tasks::Widget widget_;
  TextPainter& painter_;
  ScreenLayout layout_;
  AnswerBand band_;
  std::string answerWord_, selectedWord_, noneWord_;  // "Answer:", "Selected:", "none" in the session's language
  Canvas base_;
  std::optional<LiveView> live_;
  std::vector<std::string> labels_;
  std::vector<glm::dvec2> screenPoints_;
  std::vector<Button> buttons_;
  nlohmann::json layoutJson_;
  std::string typed_;
  std::vector<std::string> refusal_;  // the last refusal, as the band shows it
  std::set<std::string> selected_;
  glm::dvec2 gauge_{0.0};         // (slant, tilt) in degrees
  glm::dvec2 gaugePointer_{0.0};  // where the drag is, in screen pixels
  std::vector<std::string> liveInputs_;  // what moved the live view since the last frame shown
  int liveShown_ = 0;                    // live pictures shown (logged) so far
  bool dirty_ = true;
};

}  // namespace tlab::study
