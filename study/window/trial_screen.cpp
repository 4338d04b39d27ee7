#include "study/window/trial_screen.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>

#include "study/window/window_style.hpp"
#include "tasks/letter_patterns.hpp"

namespace tlab::study {

namespace {

using tasks::AnswerKind;

std::string hint(AnswerKind kind) {
  switch (kind) {
    case AnswerKind::LayerNumber: return "Type the layer number (1 = front) and press Enter.";
    case AnswerKind::Count: return "Type the number and press Enter.";
    case AnswerKind::Label: return "Click the label (or type it and press Enter).";
    case AnswerKind::LabelSet: return "Click labels to select them, then press Enter (Enter with none selected: none).";
    case AnswerKind::Letter: return "Click the letter (or press its key).";
    case AnswerKind::FloorPoint: return "Click the place on the floor plan (right), or type x,z and press Enter.";
  }
  return "";
}

std::string formatCountdown(double seconds) {
  const int s = std::max(0, int(std::ceil(seconds)));
  char buf[32];
  std::snprintf(buf, sizeof buf, "%d:%02d", s / 60, s % 60);
  return buf;
}

bool hasFloorPlan(const TrialView& view) {
  return view.prepared.question.answerKind == AnswerKind::FloorPoint && view.prepared.floorPlan.has_value();
}

}  // namespace

TrialScreen::TrialScreen(const TrialView& view, Canvas blank, TextPainter& painter) : view_(view), painter_(painter), base_(std::move(blank)) {
  const tasks::Question& q = view.prepared.question;
  const Canvas& stimulus = *view.prepared.stimulus;
  layout_ = hasFloorPlan(view) ? makeScreenLayoutWithPlan(base_.width(), base_.height(), stimulus.width(), stimulus.height())
                               : makeScreenLayout(base_.width(), base_.height(), stimulus.width(), stimulus.height());
  // Interactive trials render the scene live in the stimulus area (Elmqvist: orbit / walk).
  if (view.plan.navigation != Navigation::None && view.prepared.scene)
    live_.emplace(view.prepared.scene, view.plan.stimulus, view.plan.navigation, view.prepared.camera);
  base_.fillRect(layout_.header, kBand);
  base_.fillRect(layout_.answer, kBand);
  base_.drawCanvas(stimulus, layout_.stimulus);
  layoutJson_ = {{"stimulus", {layout_.stimulus.x, layout_.stimulus.y, layout_.stimulus.width, layout_.stimulus.height}},
                 {"canvas", {base_.width(), base_.height()}}};
  if (hasFloorPlan(view)) {
    base_.drawCanvas(*view.prepared.floorPlanImage, *layout_.plan);
    base_.strokeRect(*layout_.plan, kInk, 1);
    layoutJson_["plan"] = {layout_.plan->x, layout_.plan->y, layout_.plan->width, layout_.plan->height};
  }
  painter_.drawLine(base_, q.text, 16, 12, 22.0f, kInk);
  painter_.drawLine(base_, hint(q.answerKind), 16, layout_.answer.y + 8, 18.0f, kMuted);
  char counter[64];  // training and test trials are counted apart
  std::snprintf(counter, sizeof counter, "%s %d/%d", view.plan.phase == Phase::Training ? "training" : "trial", view.index, view.total);
  painter_.drawLine(base_, counter, base_.width() - 260, 12, 18.0f, kMuted);
  for (const auto& p : q.points) {
    if (!isMarkedPoint(p)) continue;
    if (q.answerKind == AnswerKind::Label && p.role != "candidate") continue;
    if (q.answerKind == AnswerKind::LabelSet && p.role != "mark") continue;
    labels_.push_back(p.label);
    screenPoints_.push_back(layout_.toScreen(p.pixel));
    layoutJson_["labels"][p.label] = {screenPoints_.back().x, screenPoints_.back().y};
  }
  if (q.answerKind == AnswerKind::Letter) {
    std::vector<std::string> letters;
    for (const char l : tasks::patternLetters()) letters.push_back(std::string(1, l));
    buttons_ = buttonRow(layout_.answer, letters);
  }
  for (const auto& b : buttons_) layoutJson_["buttons"][b.label] = {b.rect.x + b.rect.width / 2, b.rect.y + b.rect.height / 2};
}

std::string TrialScreen::selectedText() const {
  std::string s;
  for (const auto& l : selected_) s += (s.empty() ? "" : ",") + l;
  return s;
}

Canvas TrialScreen::frame(double secondsLeft) {
  Canvas c = base_;
  if (live_) c.drawCanvas(live_->frame(), layout_.stimulus);
  painter_.drawLine(c, formatCountdown(secondsLeft), base_.width() - 100, 12, 24.0f, secondsLeft < 10 ? kWarn : kInk);
  for (std::size_t i = 0; i < labels_.size(); ++i)
    if (selected_.count(labels_[i])) c.strokeCircle(screenPoints_[i].x, screenPoints_[i].y, 10.0, 3.0, kAccent);
  for (const auto& b : buttons_) drawButton(c, painter_, b, false);
  const bool showSelection = view_.prepared.question.answerKind == AnswerKind::LabelSet && typed_.empty();
  const std::string shown = showSelection ? "selected: " + (selected_.empty() ? std::string("none") : selectedText()) : "answer: " + typed_ + "_";
  painter_.drawLine(c, shown, 16, layout_.answer.y + 40, 22.0f, kInk);
  if (!error_.empty()) painter_.drawLine(c, error_, 16, layout_.answer.y + 70, 16.0f, kWarn);
  dirty_ = false;
  return c;
}

std::optional<std::string> TrialScreen::typedChar(const std::string& ch) {
  // A pattern letter is answered by its key alone; everything else is typed and sent with Enter.
  if (view_.prepared.question.answerKind == AnswerKind::Letter && ch.size() == 1 &&
      tasks::patternLetters().find(char(std::toupper(ch[0]))) != std::string::npos)
    return std::string(1, char(std::toupper(ch[0])));
  if (typed_.size() < 256) typed_ += ch, dirty_ = true;
  return std::nullopt;
}

std::optional<std::string> TrialScreen::enter() {
  std::string text = typed_;
  if (view_.prepared.question.answerKind == AnswerKind::LabelSet && text.empty()) text = selected_.empty() ? "none" : selectedText();
  if (text.empty()) return std::nullopt;
  return text;
}

void TrialScreen::backspace() {
  dropLastCodepoint(typed_);
  dirty_ = true;
}

std::optional<std::string> TrialScreen::clickLabel(double x, double y) {
  const int hit = hitPoint(screenPoints_, {x, y});
  if (hit < 0) return std::nullopt;
  const std::string& label = labels_[std::size_t(hit)];
  if (view_.prepared.question.answerKind == AnswerKind::Label) return label;
  if (view_.prepared.question.answerKind == AnswerKind::LabelSet) {  // clicks toggle, Enter submits
    if (!selected_.erase(label)) selected_.insert(label);
    dirty_ = true;
  }
  return std::nullopt;
}

std::optional<std::string> TrialScreen::clickFloorPlan(double x, double y) const {
  if (!hasFloorPlan(view_) || !layout_.plan->contains(x, y)) return std::nullopt;
  const FloorPlan& plan = *view_.prepared.floorPlan;
  const glm::dvec2 planPixel((x - layout_.plan->x) * plan.width / double(layout_.plan->width),
                             (y - layout_.plan->y) * plan.height / double(layout_.plan->height));
  const glm::dvec2 world = plan.worldAt(planPixel);
  char text[96];
  std::snprintf(text, sizeof text, "%.4f,%.4f", world.x, world.y);
  return std::string(text);
}

std::optional<std::string> TrialScreen::click(double x, double y) {
  for (const auto& b : buttons_)
    if (b.rect.contains(x, y)) return b.label;
  if (auto floor = clickFloorPlan(x, y)) return floor;
  return clickLabel(x, y);
}

void TrialScreen::arrow(int forward, int right) {
  if (!live_) return;
  live_->navigator().move(forward, right);
  dirty_ = true;
}

void TrialScreen::drag(double dx, double dy) {
  if (!live_) return;
  live_->navigator().drag(dx, dy);
  dirty_ = true;
}

void TrialScreen::moveTo(double x, double y) {
  if (live_ && layout_.stimulus.contains(x, y))
    dirty_ = live_->pointAt({float((x - layout_.stimulus.x) / layout_.stimulus.width), float((y - layout_.stimulus.y) / layout_.stimulus.height)}) ||
             dirty_;
}

void TrialScreen::rejected(const std::string& error) {
  error_ = error;
  typed_.clear();
  dirty_ = true;
}

std::string TrialScreen::cameraText() const { return live_ ? live_->navigator().describe() : ""; }

}  // namespace tlab::study
