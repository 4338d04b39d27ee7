#include "study/serve/trial_page.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "tasks/answer_parser.hpp"
#include "tasks/letter_patterns.hpp"

namespace tlab::study {

namespace {

using nlohmann::json;
using tasks::AnswerKind;

// The labels a participant can click: candidates (Label), marks (LabelSet); none otherwise.
std::vector<const tasks::ProbePoint*> clickable(const tasks::Question& q) {
  std::vector<const tasks::ProbePoint*> out;
  for (const auto& p : q.points) {
    if (!isMarkedPoint(p)) continue;
    if (q.answerKind == AnswerKind::Label && p.role == "candidate") out.push_back(&p);
    if (q.answerKind == AnswerKind::LabelSet && p.role == "mark") out.push_back(&p);
  }
  return out;
}

bool offered(const tasks::Question& q, const std::string& label) {
  for (const auto* p : clickable(q))
    if (p->label == label) return true;
  return false;
}

std::int64_t wholeNumber(const json& v, std::int64_t minimum) {
  if (!v.is_number_integer()) throw std::invalid_argument("expected a whole number");
  const std::int64_t n = v.get<std::int64_t>();
  if (n < minimum || n > 1000000) throw std::invalid_argument("expected a whole number from " + std::to_string(minimum) + " to 1000000");
  return n;
}

std::string labelSetText(const tasks::Question& q, const json& v) {
  if (!v.is_array() || v.size() > 64) throw std::invalid_argument("expected a list of labels");
  std::string text;
  for (const auto& item : v) {
    if (!item.is_string() || !offered(q, item.get<std::string>())) throw std::invalid_argument("a label that is not on the picture");
    text += (text.empty() ? "" : ",") + item.get<std::string>();
  }
  return text.empty() ? "none" : text;
}

std::string floorPointText(const std::optional<FloorPlan>& floorPlan, const json& v) {
  if (!floorPlan) throw std::invalid_argument("this trial has no floor plan");
  const FloorPlan& plan = *floorPlan;
  if (!v.is_object() || !v.contains("x") || !v.contains("y") || !v["x"].is_number() || !v["y"].is_number())
    throw std::invalid_argument("expected {\"x\": pixel, \"y\": pixel} on the floor plan");
  const double x = v["x"].get<double>(), y = v["y"].get<double>();
  if (!(x >= 0 && y >= 0 && x < plan.width && y < plan.height)) throw std::invalid_argument("the click is outside the floor plan");
  const glm::dvec2 world = plan.worldAt({x, y});
  char text[96];
  std::snprintf(text, sizeof text, "%.4f,%.4f", world.x, world.y);  // as the window writes a click (study/window/trial_screen.cpp)
  return text;
}

std::string kindText(const tasks::Question& q, const std::optional<FloorPlan>& floorPlan, const json& v) {
  switch (q.answerKind) {
    case AnswerKind::LayerNumber: return std::to_string(wholeNumber(v, 1));
    case AnswerKind::Count: return std::to_string(wholeNumber(v, 0));
    case AnswerKind::Label:
      if (!v.is_string() || !offered(q, v.get<std::string>())) throw std::invalid_argument("expected one of the labels on the picture");
      return v.get<std::string>();
    case AnswerKind::LabelSet: return labelSetText(q, v);
    case AnswerKind::Letter:
      if (!v.is_string() || v.get<std::string>().size() != 1 || tasks::patternLetters().find(v.get<std::string>()) == std::string::npos)
        throw std::invalid_argument("expected one of the letters " + tasks::patternLetters());
      return v.get<std::string>();
    case AnswerKind::FloorPoint: return floorPointText(floorPlan, v);
  }
  throw std::invalid_argument("unknown answer kind");
}

double milliseconds(const json& body, const char* key) {
  const auto it = body.find(key);
  if (it == body.end() || !it->is_number()) throw std::invalid_argument(std::string("'") + key + "' must be a number of milliseconds");
  const double v = it->get<double>();
  if (!(v >= 0.0 && v <= 1e9)) throw std::invalid_argument(std::string("'") + key + "' is out of range");
  return v;
}

json turntableJson(const Turntable& t) {
  json views = json::array();
  for (const auto& v : t.views) views.push_back({{"sha256", v.sha256}, {"azimuth", v.azimuthDegrees}, {"elevation", v.elevationDegrees}});
  return {{"azimuths", t.azimuths}, {"elevations", t.elevations}, {"start", {t.startAzimuth, t.startElevation}}, {"views", views}};
}

json pageOf(const TrialView& view, const TrialImages& images) {
  const tasks::Question& q = view.prepared.question;
  json labels = json::array();
  for (const auto* p : clickable(q)) labels.push_back({{"label", p->label}, {"x", p->pixel.x}, {"y", p->pixel.y}});
  json page{{"kind", "trial"},
            {"phase", phaseName(view.plan.phase)},
            {"index", view.index},
            {"total", view.total},
            {"question", q.text},
            {"answer_kind", tasks::answerKindName(q.answerKind)},
            {"format", tasks::answerFormat(q.answerKind)},
            {"limit_s", view.limitSeconds},
            {"image", {{"sha256", view.prepared.stimulusSha256}, {"width", view.plan.stimulus.width}, {"height", view.plan.stimulus.height}}},
            {"labels", labels}};
  if (q.answerKind == AnswerKind::Letter) {
    json letters = json::array();
    for (const char l : tasks::patternLetters()) letters.push_back(std::string(1, l));
    page["letters"] = letters;
  }
  if (view.prepared.floorPlan && !images.floorPlanSha256.empty())
    page["floor_plan"] = {{"sha256", images.floorPlanSha256}, {"width", view.prepared.floorPlan->width}, {"height", view.prepared.floorPlan->height}};
  if (images.turntable) page["turntable"] = turntableJson(*images.turntable);
  return page;
}

Checked checkTrialReply(const AnswerContext& context, const std::optional<Turntable>& turntable, const json& body) {
  if (!body.is_object()) return {"reply: expected a JSON object", {}};
  const std::string type = body.value("type", "");
  try {
    if (type == "onset") return {"", {type, {{"painted_ms", milliseconds(body, "painted_ms")}}}};
    if (type == "timeout") return {"", {type, json::object()}};
    if (type == "view") {
      if (!turntable) throw std::invalid_argument("this trial has no turntable");
      const std::int64_t a = body.value("azimuth", -1), e = body.value("elevation", -1);
      if (a < 0 || e < 0 || a >= turntable->azimuths || e >= turntable->elevations) throw std::invalid_argument("no such view");
      return {"", {type, {{"view", turntable->views[std::size_t(e * turntable->azimuths + a)].camera}, {"t_ms", milliseconds(body, "t_ms")}}}};
    }
    if (type == "answer") {
      if (!body.contains("answer")) throw std::invalid_argument("'answer' is missing");
      const std::string text = answerText(context, body["answer"]);
      json value{{"text", text}, {"rt_ms", milliseconds(body, "rt_ms")}};
      for (const char* key : {"painted_ms", "input_ms"})  // the page's clock at the paint and at the input, when sent
        if (body.contains(key)) value[key] = milliseconds(body, key);
      return {"", {type, value}};
    }
  } catch (const std::exception& e) {  // json type errors included
    return {std::string(type.empty() ? "reply" : type) + ": " + e.what(), {}};
  }
  return {"unknown reply type '" + type.substr(0, 40) + "' (expected onset, view, answer or timeout)", {}};
}

}  // namespace

std::string answerText(const AnswerContext& context, const nlohmann::json& answer) {
  const std::string text = kindText(context.question, context.floorPlan, answer);
  try {
    tasks::parseAnswer(context.question, text);  // the task's own parser agrees
  } catch (const tasks::AnswerFormatError& e) {
    throw std::invalid_argument(e.what());
  }
  return text;
}

Screen trialScreen(const TrialView& view, const TrialImages& images) {
  Screen s;
  s.page = pageOf(view, images);
  s.images.insert(view.prepared.stimulusSha256);
  if (!images.floorPlanSha256.empty()) s.images.insert(images.floorPlanSha256);
  if (images.turntable)
    for (const auto& v : images.turntable->views) s.images.insert(v.sha256);
  // Copies: a late reply may be checked after the runner's view has gone.
  s.check = [context = AnswerContext{view.prepared.question, view.prepared.floorPlan}, turntable = images.turntable](const json& body) {
    return checkTrialReply(context, turntable, body);
  };
  return s;
}

}  // namespace tlab::study
