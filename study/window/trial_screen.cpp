#include "study/window/trial_screen.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>

#include "study/run/session_wording.hpp"
#include "study/window/window_style.hpp"
#include "study/window/gauge_drawing.hpp"
#include "study/window/trial_header.hpp"
#include "study/window/answer_band.hpp"

namespace tlab::study {

namespace {

using tasks::WidgetKind;

std::string formatCountdown(double seconds) {
  const int s = std::max(0, int(std::ceil(seconds)));
  char buf[32];
  std::snprintf(buf, sizeof buf, "%d:%02d", s / 60, s % 60);
  return buf;
}

bool hasFloorPlan(const TrialView& view, const tasks::Widget& widget) {
  return widget.kind == WidgetKind::FloorPlanPoint && view.prepared.floorPlan.has_value();
}

}  // namespace

TrialScreen::TrialScreen(const TrialView& view, Canvas blank, TextPainter& painter, const ParticipantTexts& texts)
    : view_(view), form_(tasks::answerForm(view.prepared.question)), widget_(form_.widget(view.prepared.question)), painter_(painter),
      base_(std::move(blank)) {
  const tasks::Question& q = view.prepared.question;
  const Canvas& stimulus = *view.prepared.stimulus;
  const bool plan = hasFloorPlan(view, widget_);
  const std::string counter = texts.format(view.plan.phase == Phase::Training ? "trial.progress_practice" : "trial.progress_test",
                                           {{"index", std::to_string(view.index)}, {"total", std::to_string(view.total)}});  // counted apart
  const TrialHeader header =
      layoutTrialHeader(painter_, questionWording(q, texts), counter, base_.width(), defaultHeaderHeight(base_.height()));
  // Interactive trials render the scene live in the stimulus area (Elmqvist: orbit / walk).
  if (view.plan.navigation != Navigation::None && view.prepared.scene)
    live_.emplace(view.prepared.scene, view.plan.stimulus, view.plan.navigation, view.prepared.camera);
  // How to answer here (the window also takes typed labels), by the answer's kind; how to move
  // in the scene below it.
  band_ = layoutAnswerBand(painter_, texts.text(std::string("window_answer.") + form_.name()),
                           live_ ? texts.text(std::string("live.") + navigationName(view.plan.navigation)) : std::string(),
                           !widget_.buttons.empty(), base_.width(), defaultAnswerHeight(base_.height()));
  layout_ = plan ? makeScreenLayoutWithPlan(base_.width(), base_.height(), stimulus.width(), stimulus.height(), header.height,
                                            band_.height)
                 : makeScreenLayout(base_.width(), base_.height(), stimulus.width(), stimulus.height(), header.height,
                                    band_.height);
  answerWord_ = texts.text("window.answer");
  selectedWord_ = texts.text("window.selected");
  noneWord_ = texts.text("window.selected_none");
  base_.fillRect(layout_.header, kBand);
  base_.fillRect(layout_.answer, kBand);
  base_.drawCanvas(stimulus, layout_.stimulus);
  layoutJson_ = {{"stimulus", {layout_.stimulus.x, layout_.stimulus.y, layout_.stimulus.width, layout_.stimulus.height}},
                 {"answer", {layout_.answer.x, layout_.answer.y, layout_.answer.width, layout_.answer.height}},
                 {"canvas", {base_.width(), base_.height()}}};
  if (plan) {
    base_.drawCanvas(*view.prepared.floorPlanImage, *layout_.plan);
    base_.strokeRect(*layout_.plan, kInk, 1);
    layoutJson_["plan"] = {layout_.plan->x, layout_.plan->y, layout_.plan->width, layout_.plan->height};
  }
  for (std::size_t i = 0; i < header.questionLines.size(); ++i)
    painter_.drawLine(base_, header.questionLines[i], kHeaderMargin, kHeaderTop + int(i) * painter_.lineHeight(kQuestionPixels),
                      kQuestionPixels, kInk);
  painter_.drawLine(base_, counter, header.counterX, kHeaderTop, kCounterPixels, kMuted);
  drawLines(base_, band_.hintLines, band_.hintTop, kHintPixels, kMuted);
  drawLines(base_, band_.liveLines, band_.liveTop, kLiveHintPixels, kMuted);
  for (const auto& p : widget_.marks) {
    labels_.push_back(p.label);
    screenPoints_.push_back(layout_.toScreen(p.pixel));
    layoutJson_["labels"][p.label] = {screenPoints_.back().x, screenPoints_.back().y};
  }
  if (!widget_.buttons.empty()) buttons_ = buttonRow(layout_.answer, widget_.buttons);
  for (const auto& b : buttons_) layoutJson_["buttons"][b.label] = {b.rect.x + b.rect.width / 2, b.rect.y + b.rect.height / 2};
  if (widget_.kind == WidgetKind::Gauge) {
    gauge_ = {widget_.startSlant, widget_.startTilt};
    const glm::dvec2 centre = layout_.toScreen(widget_.at);
    layoutJson_["gauge"] = {{"centre", {centre.x, centre.y}}, {"radius", gaugeRadius()}, {"start", {gauge_.x, gauge_.y}}};
  }
}

void TrialScreen::drawLines(Canvas& c, const std::vector<std::string>& lines, int top, float pixels, Rgba color) {
  for (std::size_t i = 0; i < lines.size(); ++i)
    painter_.drawLine(c, lines[i], kAnswerMargin, layout_.answer.y + top + int(i) * painter_.lineHeight(pixels), pixels, color);
}

double TrialScreen::gaugeRadius() const { return widget_.radiusPixels * layout_.stimulus.width / double(layout_.stimulusWidth); }

std::string TrialScreen::selectedText() const {
  std::string s;
  for (const auto& l : selected_) s += (s.empty() ? "" : ",") + l;
  return s;
}

Canvas TrialScreen::frame(double secondsLeft) {
  Canvas c = base_;
  if (live_) c.drawCanvas(live_->frame(), layout_.stimulus);
  painter_.drawLine(c, formatCountdown(secondsLeft), base_.width() - kCountdownReserve, kHeaderTop, kCountdownPixels,
                    secondsLeft < 10 ? kWarn : kInk);
  for (std::size_t i = 0; i < labels_.size(); ++i)
    if (selected_.count(labels_[i])) c.strokeCircle(screenPoints_[i].x, screenPoints_[i].y, 10.0, 3.0, kAccent);
  for (const auto& b : buttons_) drawButton(c, painter_, b, false);
  if (widget_.kind == WidgetKind::Gauge) drawGauge(c, layout_.toScreen(widget_.at), gaugeRadius(), gauge_.x, gauge_.y);
  const bool showSelection = widget_.kind == WidgetKind::PickLabels && typed_.empty();
  const std::string shown = showSelection ? selectedWord_ + " " + (selected_.empty() ? noneWord_ : selectedText())
                                          : answerWord_ + " " + typed_ + "_";
  painter_.drawLine(c, shown, kAnswerMargin, layout_.answer.y + band_.answerTop, kAnswerPixels, kInk);
  drawLines(c, refusal_, band_.refusalTop, kRefusalPixels, kWarn);
  dirty_ = false;
  return c;
}

std::optional<std::string> TrialScreen::typedChar(const std::string& ch) {
  // A button's one-letter label is answered by its key alone; everything else is typed and sent with Enter.
  if (ch.size() == 1)
    for (const auto& b : widget_.buttons)
      if (b.size() == 1 && b[0] == char(std::toupper(ch[0]))) return b;
  if (typed_.size() < 256) typed_ += ch, dirty_ = true;
  return std::nullopt;
}

std::optional<std::string> TrialScreen::enter() {
  const std::string& text = typed_;
  if (text.find_first_not_of(" \t") != std::string::npos) return text;  // blanks alone are no typed answer
  if (widget_.kind == WidgetKind::PickLabels) return selected_.empty() ? "none" : selectedText();
  if (widget_.kind == WidgetKind::Gauge) return form_.fromInput(view_.prepared.question, tasks::GaugeSetting{gauge_.x, gauge_.y});
  return std::nullopt;
}

void TrialScreen::backspace() {
  dropLastCodepoint(typed_);
  dirty_ = true;
}

std::optional<std::string> TrialScreen::clickLabel(double x, double y) {
  const int hit = hitPoint(screenPoints_, {x, y});
  if (hit < 0) return std::nullopt;
  const std::string& label = labels_[std::size_t(hit)];
  if (widget_.kind == WidgetKind::PickLabel) return label;
  if (widget_.kind == WidgetKind::PickLabels) {  // clicks toggle, Enter submits
    if (!selected_.erase(label)) selected_.insert(label);
    dirty_ = true;
  }
  return std::nullopt;
}

std::optional<std::string> TrialScreen::clickFloorPlan(double x, double y) const {
  if (!hasFloorPlan(view_, widget_) || !layout_.plan->contains(x, y)) return std::nullopt;
  const FloorPlan& plan = *view_.prepared.floorPlan;
  const glm::dvec2 planPixel((x - layout_.plan->x) * plan.width / double(layout_.plan->width),
                             (y - layout_.plan->y) * plan.height / double(layout_.plan->height));
  return form_.fromInput(view_.prepared.question, tasks::PlanPoint{plan.worldAt(planPixel)});
}

std::optional<std::string> TrialScreen::click(double x, double y) {
  for (const auto& b : buttons_)
    if (b.rect.contains(x, y)) return b.label;
  if (auto floor = clickFloorPlan(x, y)) return floor;
  if (widget_.kind == WidgetKind::Gauge && layout_.stimulus.contains(x, y)) {  // the stick follows the pointer
    gaugePointer_ = {x, y};
    gauge_ = gaugeToward(layout_.toScreen(widget_.at), gaugeRadius(), gaugePointer_);
    dirty_ = true;
    return std::nullopt;
  }
  return clickLabel(x, y);
}

bool TrialScreen::takesArrows() const { return live_.has_value() || widget_.kind == WidgetKind::Gauge; }

void TrialScreen::arrow(int forward, int right) {
  if (widget_.kind == WidgetKind::Gauge) {  // up/down: slant ± 2°, left/right: tilt ± 5°
    gauge_.x = std::clamp(gauge_.x + 2.0 * forward, 0.0, 85.0);
    gauge_.y = std::fmod(gauge_.y - 5.0 * right + 360.0, 360.0);
    dirty_ = true;
    return;
  }
  if (!live_) return;
  live_->navigator().move(forward, right);
  liveInputs_.push_back(frameInputPart("key", forward, right));
  dirty_ = true;
}

void TrialScreen::drag(double dx, double dy) {
  if (widget_.kind == WidgetKind::Gauge) {
    gaugePointer_ += glm::dvec2(dx, dy);
    gauge_ = gaugeToward(layout_.toScreen(widget_.at), gaugeRadius(), gaugePointer_);
    dirty_ = true;
    return;
  }
  if (!live_) return;
  live_->navigator().drag(dx, dy);
  liveInputs_.push_back(frameInputPart("drag", dx, dy));
  dirty_ = true;
}

void TrialScreen::moveTo(double x, double y) {
  if (!live_ || !layout_.stimulus.contains(x, y)) return;
  const glm::vec2 at(float((x - layout_.stimulus.x) / layout_.stimulus.width), float((y - layout_.stimulus.y) / layout_.stimulus.height));
  if (!live_->pointAt(at)) return;
  liveInputs_.push_back(frameInputPart("point", at.x, at.y));
  dirty_ = true;
}

std::optional<LiveFrame> TrialScreen::shownLiveFrame(std::int64_t shownNs) {
  if (!live_ || live_->rendered().count == liveShown_) return std::nullopt;
  const LiveView::Rendered& r = live_->rendered();
  std::string input = liveShown_ == 0 ? "start" : "";
  for (const auto& i : liveInputs_) input += (input.empty() ? "" : "; ") + i;
  liveInputs_.clear();
  liveShown_ = r.count;
  // Hashed here, once per picture shown: only pictures that reached the screen cost a hash.
  return LiveFrame{r.count - 1, r.camera, r.lens, input, shownNs, framePixelsSha256(live_->frame())};
}

void TrialScreen::rejected(const std::string& error) {
  refusal_ = refusalLines(painter_, error, band_);
  typed_.clear();
  dirty_ = true;
}

std::string TrialScreen::cameraText() const {
  if (widget_.kind == WidgetKind::Gauge) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "gauge slant=%.2f tilt=%.2f", gauge_.x, gauge_.y);
    return buf;
  }
  return live_ ? live_->navigator().describe() : "";
}

}  // namespace tlab::study
