// WindowResponder: the window and its input callbacks, frames presented, the autopilot's
// scripted inputs, pauses and plain messages. Trials: window_trial.cpp; forms, consent, feedback
// and breaks: window_screens.cpp.
#include "study/window/window_responder.hpp"

#include "study/run/live_view.hpp"
#include "study/window/trial_screen.hpp"
#include "study/run/simulated_observer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

#include "study/window/window_style.hpp"
#include "tasks/answer_parser.hpp"
#include "tasks/letter_patterns.hpp"

namespace tlab::study {

namespace {

WindowResponder* self(GLFWwindow* w) { return static_cast<WindowResponder*>(glfwGetWindowUserPointer(w)); }

void onKey(GLFWwindow* w, int key, int, int action, int) {
  if (action == GLFW_PRESS || action == GLFW_REPEAT) self(w)->push({WindowResponder::Input::Kind::Key, key, 0, 0, 0, monotonicNs()});
}
void onChar(GLFWwindow* w, unsigned int codepoint) {
  self(w)->push({WindowResponder::Input::Kind::Char, 0, char32_t(codepoint), 0, 0, monotonicNs()});
}
void onMouse(GLFWwindow* w, int button, int action, int) {
  if (button != GLFW_MOUSE_BUTTON_LEFT) return;
  const std::int64_t t = monotonicNs();
  double x = 0, y = 0;
  glfwGetCursorPos(w, &x, &y);
  const glm::dvec2 p = self(w)->cursorToCanvas(x, y);
  if (action == GLFW_PRESS) {
    self(w)->pressAt(p);
    self(w)->push({WindowResponder::Input::Kind::Click, 0, 0, p.x, p.y, t});
  } else if (action == GLFW_RELEASE) {
    self(w)->release();
  }
}
// While the left button is held, cursor motion arrives as drags (dx, dy in canvas pixels).
void onCursor(GLFWwindow* w, double x, double y) {
  const glm::dvec2 p = self(w)->cursorToCanvas(x, y);
  self(w)->push({WindowResponder::Input::Kind::Move, 0, 0, p.x, p.y, monotonicNs()});
  if (const auto delta = self(w)->dragTo(p)) self(w)->push({WindowResponder::Input::Kind::Drag, 0, 0, delta->x, delta->y, monotonicNs()});
}
void onClose(GLFWwindow* w) { self(w)->push({WindowResponder::Input::Kind::Close, 0, 0, 0, 0, monotonicNs()}); }



}  // namespace

std::unique_ptr<gpu::WindowContext> openParticipantWindow(int width, int height, const std::string& title) {
  try {
    return gpu::createWindowContext(width, height, title);
  } catch (const std::exception& e) {
    const std::string why = std::string(e.what()).substr(0, std::string(e.what()).find(" - "));  // without the render hint
    throw std::runtime_error("tlab run shows the session in a window and cannot open one (" + why +
                             "): run it on a machine with a display, under a virtual one (xvfb-run tlab run ...), "
                             "or pilot the study without a window with tlab simulate");
  }
}

void makeFullscreen(gpu::WindowContext& window) {
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
  if (!mode) throw std::runtime_error("--fullscreen: no monitor found");
  glfwSetWindowMonitor(window.handle(), monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}

WindowResponder::WindowResponder(gpu::WindowContext& window, TextPainter& painter) : window_(window), painter_(painter) {
  GLFWwindow* w = window_.handle();
  glfwSetWindowUserPointer(w, this);
  glfwSetKeyCallback(w, onKey);
  glfwSetCharCallback(w, onChar);
  glfwSetMouseButtonCallback(w, onMouse);
  glfwSetCursorPosCallback(w, onCursor);
  glfwSetWindowCloseCallback(w, onClose);
  glfwSwapInterval(1);
}

WindowResponder::~WindowResponder() {
  GLFWwindow* w = window_.handle();
  glfwSetKeyCallback(w, nullptr);
  glfwSetCharCallback(w, nullptr);
  glfwSetMouseButtonCallback(w, nullptr);
  glfwSetCursorPosCallback(w, nullptr);
  glfwSetWindowCloseCallback(w, nullptr);
  glfwSetWindowUserPointer(w, nullptr);
}

void WindowResponder::pressAt(glm::dvec2 p) { dragFrom_ = p; }
void WindowResponder::release() { dragFrom_.reset(); }
std::optional<glm::dvec2> WindowResponder::dragTo(glm::dvec2 p) {
  if (!dragFrom_) return std::nullopt;
  const glm::dvec2 delta = p - *dragFrom_;
  dragFrom_ = p;
  return delta;
}

glm::dvec2 WindowResponder::cursorToCanvas(double x, double y) const {
  int ww = 1, wh = 1, fw = 1, fh = 1;
  glfwGetWindowSize(window_.handle(), &ww, &wh);
  glfwGetFramebufferSize(window_.handle(), &fw, &fh);
  return {x * fw / std::max(ww, 1), y * fh / std::max(wh, 1)};
}

Canvas WindowResponder::blank() const {
  int fw = 1, fh = 1;
  glfwGetFramebufferSize(window_.handle(), &fw, &fh);
  return Canvas(std::max(fw, 64), std::max(fh, 64), kPaper);
}

std::int64_t WindowResponder::present(const Canvas& canvas) {
  const std::int64_t before = monotonicNs();
  window_.present(canvas.rgba().data(), canvas.width(), canvas.height());
  const std::int64_t after = monotonicNs();
  lastPresentMs_ = (after - before) / 1e6;
  ++frames_;
  presentSumMs_ += lastPresentMs_;
  presentMaxMs_ = std::max(presentMaxMs_, lastPresentMs_);
  return after;
}

void WindowResponder::engageAutopilot(std::shared_ptr<SimulatedObserver> observer, double pace) {
  autopilot_ = std::move(observer);
  autopilotPace_ = pace;
}

void WindowResponder::script(std::vector<Input> inputs, double afterSeconds) {
  if (!autopilot_) return;
  const std::int64_t due = monotonicNs() + std::int64_t(afterSeconds * 1e9);
  for (auto& in : inputs) script_.push_back({due, in});
}

void WindowResponder::scriptText(const std::string& text, bool enter, double afterSeconds) {
  std::vector<Input> inputs;
  for (const unsigned char c : text) inputs.push_back({Input::Kind::Char, 0, char32_t(c), 0, 0, 0});
  if (enter) inputs.push_back({Input::Kind::Key, GLFW_KEY_ENTER, 0, 0, 0, 0});
  script(inputs, afterSeconds);
}

void WindowResponder::waitForInput(double seconds, bool inTrial) {
  const std::int64_t before = monotonicNs();
  if (!script_.empty()) seconds = std::min(seconds, std::max(0.0, (script_.front().first - before) / 1e9));
  glfwWaitEventsTimeout(std::max(seconds, 0.0));
  while (!script_.empty() && script_.front().first <= monotonicNs()) {  // the autopilot's keys, stamped when given
    Input in = script_.front().second;
    in.tNs = monotonicNs();
    inputs_.push_back(in);
    script_.pop_front();
  }
  if (inTrial) eventWaitMaxMs_ = std::max(eventWaitMaxMs_, (monotonicNs() - before) / 1e6);
}

void WindowResponder::event(std::int64_t tNs, const std::string& kind, const std::string& detail) {
  events_.push_back({tNs, kind, detail});
}

std::vector<ResponderEvent> WindowResponder::takeEvents() {
  std::vector<ResponderEvent> out;
  out.swap(events_);
  return out;
}

bool WindowResponder::pause() {
  event(monotonicNs(), "pause", "");
  Canvas c = blank();
  painter_.drawLine(c, texts().text("window.paused"), 40, c.height() / 3, 36.0f, kInk);
  painter_.drawLine(c, texts().text("window.continue"), 40, c.height() / 3 + 60, 22.0f, kMuted);
  present(c);
  while (!closed_) {
    waitForInput(0.1);
    while (!inputs_.empty()) {
      const Input in = inputs_.front();
      inputs_.pop_front();
      if (in.kind == Input::Kind::Close) closed_ = true;
      if (in.kind == Input::Kind::Key && (in.key == GLFW_KEY_SPACE || in.key == GLFW_KEY_ENTER)) {
        inputs_.clear();
        event(monotonicNs(), "resume", "");
        return true;
      }
    }
    present(c);
  }
  return false;
}

bool WindowResponder::showMessage(const std::string& title, const std::string& text) {
  if (closed_) return false;
  Canvas c = blank();
  painter_.drawLine(c, title, 40, 40, 32.0f, kInk);
  painter_.drawParagraph(c, text, 40, 100, c.width() - 80, 22.0f, kInk);
  painter_.drawLine(c, texts().text("window.continue_or_click"), 40, c.height() - 60, 20.0f, kMuted);
  present(c);
  inputs_.clear();
  script({{Input::Kind::Key, GLFW_KEY_SPACE, 0, 0, 0, 0}}, 0.2);
  while (const auto in = nextInput(c))
    if (in->kind == Input::Kind::Click || (in->kind == Input::Kind::Key && (in->key == GLFW_KEY_SPACE || in->key == GLFW_KEY_ENTER)))
      return true;
  return false;
}

FrameTiming WindowResponder::timing() const {
  FrameTiming t;
  t.frames = frames_;
  t.presentMeanMs = frames_ ? presentSumMs_ / frames_ : 0.0;
  t.presentMaxMs = presentMaxMs_;
  t.onsets = onsets_;
  t.onsetMeanMs = onsets_ ? onsetSumMs_ / onsets_ : 0.0;
  t.onsetMaxMs = onsetMaxMs_;
  t.eventWaitMaxMs = eventWaitMaxMs_;
  std::int64_t smallest = INT64_MAX;
  for (int i = 0; i < 10000; ++i) {
    const std::int64_t a = monotonicNs();
    std::int64_t b = monotonicNs();
    while (b == a) b = monotonicNs();
    smallest = std::min(smallest, b - a);
  }
  t.clockResolutionNs = double(smallest);
  return t;
}

}  // namespace tlab::study
