#include "study/run/window_responder.hpp"

#include "study/run/live_view.hpp"
#include "study/simulate/simulated_observer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

#include "study/run/window_style.hpp"
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

std::string hint(tasks::AnswerKind kind) {
  using tasks::AnswerKind;
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

}  // namespace

std::int64_t monotonicNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
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
  painter_.drawLine(c, "Paused", 40, c.height() / 3, 36.0f, kInk);
  painter_.drawLine(c, "Press Space to continue.", 40, c.height() / 3 + 60, 22.0f, kMuted);
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
  painter_.drawLine(c, "Press Space or click to continue.", 40, c.height() - 60, 20.0f, kMuted);
  present(c);
  inputs_.clear();
  script({{Input::Kind::Key, GLFW_KEY_SPACE, 0, 0, 0, 0}}, 0.2);
  while (const auto in = nextInput(c))
    if (in->kind == Input::Kind::Click || (in->kind == Input::Kind::Key && (in->key == GLFW_KEY_SPACE || in->key == GLFW_KEY_ENTER)))
      return true;
  return false;
}

std::optional<Response> WindowResponder::respond(const TrialView& view) {
  if (closed_) return std::nullopt;
  const tasks::Question& q = view.prepared.question;
  const Canvas& stimulus = *view.prepared.stimulus;
  Canvas base = blank();
  const bool floorAnswer = q.answerKind == tasks::AnswerKind::FloorPoint && view.prepared.floorPlan;
  // Interactive trials render the scene live in the stimulus area (Elmqvist: orbit / walk).
  std::optional<LiveView> live;
  if (view.plan.navigation != Navigation::None && view.prepared.scene)
    live.emplace(view.prepared.scene, view.plan.stimulus, view.plan.navigation, view.prepared.camera);
  const ScreenLayout layout = floorAnswer ? makeScreenLayoutWithPlan(base.width(), base.height(), stimulus.width(), stimulus.height())
                                          : makeScreenLayout(base.width(), base.height(), stimulus.width(), stimulus.height());
  base.fillRect(layout.header, kBand);
  base.fillRect(layout.answer, kBand);
  base.drawCanvas(stimulus, layout.stimulus);
  if (floorAnswer) {
    base.drawCanvas(*view.prepared.floorPlanImage, *layout.plan);
    base.strokeRect(*layout.plan, kInk, 1);
  }
  painter_.drawLine(base, q.text, 16, 12, 22.0f, kInk);
  painter_.drawLine(base, hint(q.answerKind), 16, layout.answer.y + 8, 18.0f, kMuted);
  char counter[64];
  std::snprintf(counter, sizeof counter, "%s %d/%d", view.plan.phase == Phase::Training ? "training" : "trial", view.index, view.total);
  painter_.drawLine(base, counter, base.width() - 260, 12, 18.0f, kMuted);

  std::vector<std::string> labels;
  std::vector<glm::dvec2> screenPoints;
  nlohmann::json layoutJson = {{"stimulus", {layout.stimulus.x, layout.stimulus.y, layout.stimulus.width, layout.stimulus.height}},
                               {"canvas", {base.width(), base.height()}}};
  for (const auto& p : q.points) {
    if (!isMarkedPoint(p)) continue;
    if (q.answerKind == tasks::AnswerKind::Label && p.role != "candidate") continue;
    if (q.answerKind == tasks::AnswerKind::LabelSet && p.role != "mark") continue;
    labels.push_back(p.label);
    screenPoints.push_back(layout.toScreen(p.pixel));
    layoutJson["labels"][p.label] = {screenPoints.back().x, screenPoints.back().y};
  }
  std::vector<Button> buttons;
  if (q.answerKind == tasks::AnswerKind::Letter) {
    std::vector<std::string> letters;
    for (const char l : tasks::patternLetters()) letters.push_back(std::string(1, l));
    buttons = buttonRow(layout.answer, letters);
  }
  for (const auto& b : buttons) layoutJson["buttons"][b.label] = {b.rect.x + b.rect.width / 2, b.rect.y + b.rect.height / 2};
  if (floorAnswer) layoutJson["plan"] = {layout.plan->x, layout.plan->y, layout.plan->width, layout.plan->height};

  std::string typed, error;
  std::set<std::string> selected;
  std::int64_t pausedNs = 0;
  std::int64_t onsetNs = 0;
  int shownSecond = -1;
  bool dirty = true;
  auto elapsed = [&](std::int64_t t) { return (t - onsetNs - pausedNs) / 1e9; };
  auto frame = [&]() {
    Canvas c = base;
    if (live) c.drawCanvas(live->frame(), layout.stimulus);
    const double left = onsetNs ? view.limitSeconds - elapsed(monotonicNs()) : view.limitSeconds;
    const std::string countdown = formatCountdown(left);
    painter_.drawLine(c, countdown, base.width() - 100, 12, 24.0f, left < 10 ? kWarn : kInk);
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (selected.count(labels[i])) c.strokeCircle(screenPoints[i].x, screenPoints[i].y, 10.0, 3.0, kAccent);
    for (const auto& b : buttons) drawButton(c, painter_, b, false);
    const std::string shown = q.answerKind == tasks::AnswerKind::LabelSet && typed.empty()
                                  ? "selected: " + (selected.empty() ? std::string("none") : [&] {
                                      std::string s;
                                      for (const auto& l : selected) s += (s.empty() ? "" : ",") + l;
                                      return s;
                                    }())
                                  : "answer: " + typed + "_";
    painter_.drawLine(c, shown, 16, layout.answer.y + 40, 22.0f, kInk);
    if (!error.empty()) painter_.drawLine(c, error, 16, layout.answer.y + 70, 16.0f, kWarn);
    return c;
  };

  inputs_.clear();
  // Frames are presented at the refresh rate throughout the trial (PsychoPy's frame record): the
  // interval of every swap is known, and frames over 1.5 refresh intervals count as late.
  const double refreshMs = 1000.0 / (refreshHz() > 0 ? refreshHz() : 60);
  std::optional<double> onsetFrameMs;
  int lateFrames = 0;
  std::int64_t lastSwapNs = 0;
  Canvas current = frame();
  auto show = [&](const Canvas& c) {
    const std::int64_t swap = present(c);
    const double interval = (swap - lastSwapNs) / 1e6;
    if (lastSwapNs == onsetNs && !onsetFrameMs) onsetFrameMs = interval;
    if (interval > 1.5 * refreshMs) ++lateFrames;
    lastSwapNs = swap;
  };
  auto timed = [&](Response r) {
    r.onsetFrameMs = onsetFrameMs;
    r.lateFrames = lateFrames;
    r.onsetToSwapMs = lastPresentOnsetMs_;
    return r;
  };
  {
    const Canvas& first = current;
    const std::int64_t before = monotonicNs();
    onsetNs = present(first);
    lastSwapNs = onsetNs;
    lastPresentOnsetMs_ = (onsetNs - before) / 1e6;
    if (autopilot_) {
      const ObserverDecision d = autopilot_->decide(view);
      scriptText(d.typed, q.answerKind != tasks::AnswerKind::Letter, std::min(d.seconds * autopilotPace_, view.limitSeconds / 2));
    }
    ++onsets_;
    const double onsetMs = (onsetNs - before) / 1e6;
    onsetSumMs_ += onsetMs;
    onsetMaxMs_ = std::max(onsetMaxMs_, onsetMs);
    layoutJson["present_ms"] = onsetMs;
    if (view.onset) view.onset(onsetNs, layoutJson.dump());  // committed now, before any answer
    else event(onsetNs, "onset", layoutJson.dump());
  }
  auto submit = [&](const std::string& text, std::int64_t t) -> std::optional<Response> {
    try {
      tasks::parseAnswer(q, text);
    } catch (const tasks::AnswerFormatError& e) {
      error = e.what();
      typed.clear();
      dirty = true;
      event(t, "invalid-answer", text);
      return std::nullopt;
    }
    Response r;
    r.text = text;
    r.onsetNs = onsetNs;
    r.responseNs = t;
    r.rtSeconds = elapsed(t);
    return r;
  };

  while (true) {
    const double left = view.limitSeconds - elapsed(monotonicNs());
    if (left <= 0) {
      Response r;
      r.onsetNs = onsetNs;
      r.responseNs = monotonicNs();
      r.note = "time limit";
      event(r.responseNs, "timeout", "");
      return timed(r);
    }
    waitForInput(std::min(0.005, left), true);
    while (!inputs_.empty()) {
      const Input in = inputs_.front();
      inputs_.pop_front();
      std::optional<Response> answer;
      if (in.kind == Input::Kind::Close) {
        closed_ = true;
        event(in.tNs, "close", "");
        return std::nullopt;
      }
      const bool arrow = in.key == GLFW_KEY_UP || in.key == GLFW_KEY_DOWN || in.key == GLFW_KEY_LEFT || in.key == GLFW_KEY_RIGHT;
      if (in.kind == Input::Kind::Key && !(live && arrow)) {
        if (in.key == GLFW_KEY_ESCAPE) {
          const std::int64_t start = monotonicNs();
          if (!pause()) return std::nullopt;
          pausedNs += monotonicNs() - start;
          dirty = true;
        } else if (in.key == GLFW_KEY_BACKSPACE) {
          dropLastCodepoint(typed);
          dirty = true;
        } else if (in.key == GLFW_KEY_ENTER || in.key == GLFW_KEY_KP_ENTER) {
          std::string text = typed;
          if (q.answerKind == tasks::AnswerKind::LabelSet && text.empty()) {
            for (const auto& l : selected) text += (text.empty() ? "" : ",") + l;
            if (text.empty()) text = "none";
          }
          if (!text.empty()) answer = submit(text, in.tNs);
        }
      } else if (in.kind == Input::Kind::Key) {  // an arrow key in a live trial
        live->navigator().move(in.key == GLFW_KEY_UP ? 1 : in.key == GLFW_KEY_DOWN ? -1 : 0,
                               in.key == GLFW_KEY_RIGHT ? 1 : in.key == GLFW_KEY_LEFT ? -1 : 0);
        event(in.tNs, "camera", live->navigator().describe());
        dirty = true;
      } else if (in.kind == Input::Kind::Move) {
        if (live && layout.stimulus.contains(in.x, in.y))
          dirty = live->pointAt({float((in.x - layout.stimulus.x) / layout.stimulus.width),
                                 float((in.y - layout.stimulus.y) / layout.stimulus.height)}) || dirty;
      } else if (in.kind == Input::Kind::Drag) {
        if (live) {
          live->navigator().drag(in.x, in.y);
          event(in.tNs, "camera", live->navigator().describe());
          dirty = true;
        }
      } else if (in.kind == Input::Kind::Char) {
        const std::string ch = utf8(in.codepoint);
        if (q.answerKind == tasks::AnswerKind::Letter && ch.size() == 1 &&
            tasks::patternLetters().find(char(std::toupper(ch[0]))) != std::string::npos)
          answer = submit(std::string(1, char(std::toupper(ch[0]))), in.tNs);
        else if (typed.size() < 256) {
          typed += ch;
          dirty = true;
        }
      } else if (in.kind == Input::Kind::Click) {
        for (const auto& b : buttons)
          if (b.rect.contains(in.x, in.y)) answer = submit(b.label, in.tNs);
        if (floorAnswer && layout.plan->contains(in.x, in.y)) {
          const FloorPlan& plan = *view.prepared.floorPlan;
          const glm::dvec2 planPixel((in.x - layout.plan->x) * plan.width / double(layout.plan->width),
                                     (in.y - layout.plan->y) * plan.height / double(layout.plan->height));
          const glm::dvec2 world = plan.worldAt(planPixel);
          char text[96];
          std::snprintf(text, sizeof text, "%.4f,%.4f", world.x, world.y);
          answer = submit(text, in.tNs);
        }
        const int hit = hitPoint(screenPoints, {in.x, in.y});
        if (hit >= 0 && q.answerKind == tasks::AnswerKind::Label) answer = submit(labels[std::size_t(hit)], in.tNs);
        if (hit >= 0 && q.answerKind == tasks::AnswerKind::LabelSet) {
          const std::string& l = labels[std::size_t(hit)];
          if (!selected.erase(l)) selected.insert(l);
          dirty = true;
        }
      }
      if (answer) {
        answer->rtSeconds = std::max(0.0, *answer->rtSeconds);
        return timed(*answer);
      }
    }
    const int second = int(std::ceil(view.limitSeconds - elapsed(monotonicNs())));
    if (dirty || second != shownSecond) {
      current = frame();
      shownSecond = second;
      dirty = false;
    }
    if ((monotonicNs() - lastSwapNs) / 1e6 >= refreshMs) show(current);
  }
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
