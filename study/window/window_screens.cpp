// WindowResponder's screens around the trials: consent, forms (participant information and
// questionnaires of every item kind, with a confirm step), training feedback, breaks, and the
// display record. Every screen logs its layout (button centres) as an event, so tests can click.
#include <algorithm>
#include <cmath>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

#include "renderer/gpu/gl.hpp"
#include "study/store/fault_point.hpp"
#include "study/design/form_field.hpp"
#include "study/run/simulated_observer.hpp"
#include "study/window/window_responder.hpp"
#include "study/window/window_style.hpp"

namespace tlab::study {

namespace {

nlohmann::json buttonCentres(const std::vector<Button>& buttons) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& b : buttons) j[b.label] = {b.rect.x + b.rect.width / 2, b.rect.y + b.rect.height / 2};
  return j;
}

// Buttons stacked vertically (choices, consent), numbered "1 ...", "2 ...".
std::vector<Button> buttonColumn(int x, int y, int width, const std::vector<std::string>& labels) {
  std::vector<Button> out;
  for (std::size_t i = 0; i < labels.size(); ++i)
    out.push_back({std::to_string(i + 1) + "  " + labels[i], Rect{x, y + int(i) * 56, width, 44}});
  return out;
}

}  // namespace

// Waits for the next input; nullopt when the window was closed (Escape pauses).
std::optional<WindowResponder::Input> WindowResponder::nextInput(const Canvas& screen) {
  while (!closed_) {
    if (inputs_.empty()) {
      waitForInput(0.1);
      if (inputs_.empty()) present(screen);  // keep the content after expose events
      continue;
    }
    const Input in = inputs_.front();
    inputs_.pop_front();
    if (in.kind == Input::Kind::Close) {
      closed_ = true;
      event(in.tNs, "close", "");
      break;
    }
    if (in.kind == Input::Kind::Key && in.key == GLFW_KEY_ESCAPE) {
      if (!pause()) break;
      present(screen);
      continue;
    }
    return in;
  }
  return std::nullopt;
}

std::optional<bool> WindowResponder::askConsent(const std::string& title, const ConsentSpec& consent) {
  if (closed_) return std::nullopt;
  Canvas c = blank();
  painter_.drawLine(c, title, 40, 40, 32.0f, kInk);
  const int bottom = 100 + painter_.drawParagraph(c, consent.text, 40, 100, c.width() - 80, 20.0f, kInk);  // returns the height used
  const auto buttons = buttonColumn(40, std::min(bottom + 30, c.height() - 150), std::min(c.width() - 80, 640),
                                    {consent.accept, consent.decline});
  for (const auto& b : buttons) drawButton(c, painter_, b, false);
  painter_.drawLine(c, texts().text("window.consent_keys"), 40, c.height() - 40, 18.0f, kMuted);
  event(present(c), "consent-screen", nlohmann::json({{"buttons", buttonCentres(buttons)}}).dump());
  inputs_.clear();
  scriptText("1", false, 0.2);
  while (const auto in = nextInput(c)) {
    int choice = 0;
    if (in->kind == Input::Kind::Char && (in->codepoint == U'1' || in->codepoint == U'2')) choice = int(in->codepoint - U'0');
    if (in->kind == Input::Kind::Click)
      for (std::size_t i = 0; i < buttons.size(); ++i)
        if (buttons[i].rect.contains(in->x, in->y)) choice = int(i) + 1;
    if (choice) {
      event(in->tNs, "consent", choice == 1 ? "accepted" : "declined");
      return choice == 1;
    }
  }
  return std::nullopt;
}

// One field on one screen; nullopt when the window was closed.
std::optional<std::string> WindowResponder::askField(const std::string& title, const FormField& field, int index, int count) {
  Canvas base = blank();
  painter_.drawLine(base, title + " (" + std::to_string(index) + "/" + std::to_string(count) + ")", 40, 30, 28.0f, kInk);
  const int bottom = 90 + painter_.drawParagraph(base, field.text, 40, 90, base.width() - 80, 24.0f, kInk);
  painter_.drawLine(base, fieldHint(field, texts()), 40, bottom + 16, 18.0f, kMuted);
  std::vector<Button> buttons;
  std::vector<std::string> values;  // what each button answers
  if (field.kind == FieldKind::Likert) {
    std::vector<std::string> labels;
    for (int k = 1; k <= field.points; ++k) labels.push_back(std::to_string(k)), values.push_back(labels.back());
    const Rect band{0, base.height() / 2, base.width(), base.height() / 4};
    buttons = buttonRow(band, labels, 56, 10);
    painter_.drawLine(base, "1 = " + field.lowAnchor, 40, band.y + band.height + 10, 18.0f, kMuted);
    const std::string high = std::to_string(field.points) + " = " + field.highAnchor;
    painter_.drawLine(base, high, base.width() - 40 - painter_.lineWidth(high, 18.0f), band.y + band.height + 10, 18.0f, kMuted);
  } else if (field.kind == FieldKind::Choice) {
    buttons = buttonColumn(40, bottom + 60, std::min(base.width() - 80, 640), field.options);
    values = field.options;
  }
  for (const auto& b : buttons) drawButton(base, painter_, b, false);
  event(present(base), "form-item", nlohmann::json({{"field", field.id}, {"buttons", buttonCentres(buttons)}}).dump());
  inputs_.clear();
  if (autopilot_) {  // a digit for buttons, typed text and Enter otherwise
    const std::string value = autopilot_->fillForm(title + ":" + field.id, {field})->front();
    const auto pick = std::find(values.begin(), values.end(), value);
    scriptText(pick != values.end() ? std::to_string(pick - values.begin() + 1) : value, pick == values.end(), 0.3);
  }
  std::string typed, error;
  const bool typing = field.kind == FieldKind::Number || field.kind == FieldKind::Text;
  auto screen = [&] {
    Canvas c = base;
    if (typing) painter_.drawLine(c, texts().format("form.typed", {{"text", typed}}), 40, base.height() / 2, 24.0f, kInk);
    if (!error.empty()) painter_.drawLine(c, error, 40, base.height() / 2 + 50, 18.0f, kWarn);
    return c;
  };
  Canvas shown = screen();
  while (const auto in = nextInput(shown)) {
    std::optional<std::string> answer;
    if (in->kind == Input::Kind::Click)
      for (std::size_t i = 0; i < buttons.size(); ++i)
        if (buttons[i].rect.contains(in->x, in->y)) answer = values[i];
    if (in->kind == Input::Kind::Char && !typing && in->codepoint >= U'1' && in->codepoint <= U'9' &&
        std::size_t(in->codepoint - U'1') < values.size())
      answer = values[std::size_t(in->codepoint - U'1')];
    if (in->kind == Input::Kind::Char && typing && typed.size() < 1000) typed += utf8(in->codepoint);
    if (in->kind == Input::Kind::Key && typing && in->key == GLFW_KEY_BACKSPACE) dropLastCodepoint(typed);
    if (in->kind == Input::Kind::Key && typing && (in->key == GLFW_KEY_ENTER || in->key == GLFW_KEY_KP_ENTER)) answer = typed;
    if (answer) {
      error = fieldError(field, *answer, texts());
      if (error.empty()) return answer;
    }
    shown = screen();
    present(shown);
  }
  return std::nullopt;
}

std::optional<std::vector<std::string>> WindowResponder::fillForm(const std::string& title, const std::vector<FormField>& fields) {
  while (!closed_) {
    std::vector<std::string> values;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const auto value = askField(title, fields[i], int(i) + 1, int(fields.size()));
      if (!value) return std::nullopt;
      values.push_back(*value);
    }
    // The confirm step: every answer once more; Enter confirms, Backspace answers again.
    Canvas c = blank();
    painter_.drawLine(c, title + ": your answers", 40, 30, 28.0f, kInk);
    int y = 90;
    for (std::size_t i = 0; i < fields.size() && y < c.height() - 120; ++i, y += 34)
      painter_.drawLine(c, fields[i].text.substr(0, 60) + ": " + (values[i].empty() ? "(no answer)" : values[i]), 40, y, 20.0f, kInk);
    painter_.drawLine(c, texts().text("window.form_confirm"), 40, c.height() - 60, 20.0f, kMuted);
    event(present(c), "form-confirm", title);
    inputs_.clear();
    script({{Input::Kind::Key, GLFW_KEY_ENTER, 0, 0, 0, 0}}, 0.3);
    while (const auto in = nextInput(c)) {
      if (in->kind != Input::Kind::Key) continue;
      if (in->key == GLFW_KEY_ENTER || in->key == GLFW_KEY_KP_ENTER) return values;
      if (in->key == GLFW_KEY_BACKSPACE) break;
    }
  }
  return std::nullopt;
}

bool WindowResponder::showFeedback(const TrialView& view, const Feedback& feedback) {
  if (closed_) return false;
  const tasks::Question& q = view.prepared.question;
  const Canvas& stimulus = *view.prepared.stimulus;
  Canvas c = blank();
  const ScreenLayout layout = makeScreenLayout(c.width(), c.height(), stimulus.width(), stimulus.height());
  c.fillRect(layout.header, kBand);
  c.fillRect(layout.answer, kBand);
  c.drawCanvas(stimulus, layout.stimulus);
  // The right answer drawn on the stimulus: its labels ringed in green.
  std::set<std::string> right;
  if (const auto* label = std::get_if<std::string>(&q.truth)) right.insert(*label);
  if (const auto* labels = std::get_if<std::set<std::string>>(&q.truth)) right = *labels;
  for (const auto& p : q.points)
    if (right.count(p.label) && isMarkedPoint(p)) {
      const glm::dvec2 s = layout.toScreen(p.pixel);
      c.strokeCircle(s.x, s.y, 16.0, 4.0, kRight);
    }
  painter_.drawLine(c, texts().text(feedback.correct ? "feedback.correct" : "feedback.wrong"), 16, 12, 26.0f, feedback.correct ? kRight : kWarn);
  painter_.drawLine(c, texts().format("feedback.right", {{"answer", feedback.rightAnswer}}), 16, layout.answer.y + 8, 22.0f, kInk);
  painter_.drawLine(c, texts().text("window.continue"), 16, layout.answer.y + 44, 18.0f, kMuted);
  event(present(c), "feedback", nlohmann::json({{"correct", feedback.correct}, {"right_answer", feedback.rightAnswer}}).dump());
  faultPoint("feedback", ++feedbacks_);
  inputs_.clear();
  script({{Input::Kind::Key, GLFW_KEY_SPACE, 0, 0, 0, 0}}, 0.5);
  while (const auto in = nextInput(c))
    if (in->kind == Input::Kind::Click || (in->kind == Input::Kind::Key && (in->key == GLFW_KEY_SPACE || in->key == GLFW_KEY_ENTER)))
      return true;
  return false;
}

bool WindowResponder::takeBreak(const BreakSpec& spec) {
  if (closed_) return false;
  const std::int64_t start = monotonicNs();
  event(start, "break", nlohmann::json({{"min_seconds", spec.minSeconds}}).dump());
  auto screen = [&](double left) {
    Canvas c = blank();
    painter_.drawLine(c, texts().text("break.title"), 40, 40, 32.0f, kInk);
    painter_.drawParagraph(c, spec.text, 40, 100, c.width() - 80, 22.0f, kInk);
    const std::string line =
        left > 0 ? texts().format("break.window_wait", {{"n", std::to_string(int(std::ceil(left)))}}) : texts().text("window.continue");
    painter_.drawLine(c, line, 40, c.height() - 60, 20.0f, kMuted);
    return c;
  };
  inputs_.clear();
  present(screen(spec.minSeconds));
  faultPoint("break", ++breaks_);
  for (double left = spec.minSeconds; left > 0 && !closed_; left = spec.minSeconds - (monotonicNs() - start) / 1e9) {
    present(screen(left));
    waitForInput(std::min(0.25, left));
    while (!inputs_.empty()) {  // keys during the minimum are ignored; closing still ends the session
      if (inputs_.front().kind == Input::Kind::Close) closed_ = true;
      inputs_.pop_front();
    }
  }
  const Canvas ready = screen(0);
  present(ready);
  script({{Input::Kind::Key, GLFW_KEY_SPACE, 0, 0, 0, 0}}, 0.2);
  while (const auto in = nextInput(ready))
    if (in->kind == Input::Kind::Key && (in->key == GLFW_KEY_SPACE || in->key == GLFW_KEY_ENTER)) {
      event(in->tNs, "break-end", nlohmann::json({{"seconds", (in->tNs - start) / 1e9}}).dump());
      return true;
    }
  return false;
}

std::optional<DisplayInfo> WindowResponder::display() const {
  DisplayInfo d;
  d.glBackend = "glfw";
  auto text = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "");
  };
  d.glVendor = text(GL_VENDOR);
  d.glRenderer = text(GL_RENDERER);
  d.glVersion = text(GL_VERSION);
  glfwGetWindowSize(window_.handle(), &d.windowWidth, &d.windowHeight);
  glfwGetFramebufferSize(window_.handle(), &d.framebufferWidth, &d.framebufferHeight);
  d.refreshHz = refreshHz();
  d.swapInterval = 1;
  return d;
}

int WindowResponder::refreshHz() const {
  GLFWmonitor* monitor = glfwGetWindowMonitor(window_.handle());
  if (!monitor) monitor = glfwGetPrimaryMonitor();
  const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
  return mode ? mode->refreshRate : 0;
}

}  // namespace tlab::study
