#include "study/serve/trial_page.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "study/serve/live_frames.hpp"
#include "tasks/answer_form.hpp"
#include "tasks/answer_parser.hpp"

namespace tlab::study {

namespace {

using nlohmann::json;

using tasks::WidgetKind;

bool offered(const tasks::Widget& widget, const std::string& label) {
  for (const auto& p : widget.marks)
    if (p.label == label) return true;
  for (const auto& b : widget.buttons)
    if (b == label) return true;
  return false;
}

std::int64_t wholeNumber(const tasks::Widget& widget, const json& v) {
  if (!v.is_number_integer()) throw std::invalid_argument("expected a whole number");
  const std::int64_t n = v.get<std::int64_t>();
  if (n < widget.minimum || n > widget.maximum) {
    const std::string min = std::to_string(widget.minimum), max = std::to_string(widget.maximum);
    // Below the minimum with no upper bound of the task's own: the participant needs to hear of the
    // minimum only; above the maximum, of the range ("0 or more" would not say what was wrong).
    if (n < widget.minimum && widget.maximum >= tasks::Widget{}.maximum)
      throw tasks::AnswerFormatError("expected a whole number from " + min + " to " + max, "refusal.whole_number_min", {{"min", min}});
    throw tasks::AnswerFormatError("expected a whole number from " + min + " to " + max, "refusal.whole_number_range", {{"min", min}, {"max", max}});
  }
  return n;
}

tasks::PickedLabels pickedLabels(const tasks::Widget& widget, const json& v) {
  if (!v.is_array() || v.size() > 64) throw std::invalid_argument("expected a list of labels");
  tasks::PickedLabels picked;
  for (const auto& item : v) {
    if (!item.is_string() || !offered(widget, item.get<std::string>())) throw std::invalid_argument("a label that is not on the picture");
    picked.labels.push_back(item.get<std::string>());
  }
  return picked;
}

tasks::PlanPoint planPoint(const std::optional<FloorPlan>& floorPlan, const json& v) {
  if (!floorPlan) throw std::invalid_argument("this trial has no floor plan");
  const FloorPlan& plan = *floorPlan;
  if (!v.is_object() || !v.contains("x") || !v.contains("y") || !v["x"].is_number() || !v["y"].is_number())
    throw std::invalid_argument("expected {\"x\": pixel, \"y\": pixel} on the floor plan");
  const double x = v["x"].get<double>(), y = v["y"].get<double>();
  if (!(x >= 0 && y >= 0 && x < plan.width && y < plan.height)) throw std::invalid_argument("the click is outside the floor plan");
  return {plan.worldAt({x, y})};
}

tasks::GaugeSetting gaugeSetting(const json& v) {
  if (!v.is_object() || !v.contains("slant") || !v.contains("tilt") || !v["slant"].is_number() || !v["tilt"].is_number())
    throw std::invalid_argument("expected {\"slant\": degrees, \"tilt\": degrees}");
  return {v["slant"].get<double>(), v["tilt"].get<double>()};
}

// The page's reply for the question's widget, as the input it stands for.
tasks::WidgetInput widgetInput(const tasks::Widget& widget, const std::optional<FloorPlan>& floorPlan, const json& v) {
  switch (widget.kind) {
    case WidgetKind::Number: return tasks::TypedText{std::to_string(wholeNumber(widget, v))};
    case WidgetKind::PickLabel:
    case WidgetKind::Buttons:
      if (!v.is_string() || !offered(widget, v.get<std::string>())) throw std::invalid_argument("expected one of the labels on the picture");
      return tasks::PickedLabels{{v.get<std::string>()}};
    case WidgetKind::PickLabels: return pickedLabels(widget, v);
    case WidgetKind::FloorPlanPoint: return planPoint(floorPlan, v);
    case WidgetKind::Gauge: return gaugeSetting(v);
  }
  throw std::invalid_argument("unknown widget");
}

json widgetJson(const tasks::Widget& w) {
  json j{{"kind", tasks::widgetName(w.kind)}};
  if (w.kind == WidgetKind::Number) j["min"] = w.minimum, j["max"] = w.maximum;
  if (!w.buttons.empty()) j["buttons"] = w.buttons;
  if (w.kind == WidgetKind::Gauge) j["gauge"] = {{"x", w.at.x}, {"y", w.at.y}, {"radius", w.radiusPixels}, {"start", {w.startSlant, w.startTilt}}};
  return j;
}

double milliseconds(const json& body, const char* key) {
  const auto it = body.find(key);
  if (it == body.end() || !it->is_number()) throw std::invalid_argument(std::string("'") + key + "' must be a number of milliseconds");
  const double v = it->get<double>();
  if (!(v >= 0.0 && v <= 1e9)) throw std::invalid_argument(std::string("'") + key + "' is out of range");
  return v;
}

// The shown size the page reports with an onset (its mode, CSS and device pixels, cm): at most 10
// numbers or short texts; null when absent.
json shownSize(const json& body) {
  const auto shown = body.find("shown");
  if (shown == body.end()) return nullptr;
  if (!shown->is_object() || shown->size() > 10) throw std::invalid_argument("'shown': expected an object of at most 10 fields");
  for (const auto& [key, value] : shown->items())
    if (key.size() > 24 || !(value.is_number() || (value.is_string() && value.get<std::string>().size() <= 16)))
      throw std::invalid_argument("'shown." + key.substr(0, 24) + "': expected a number or a short text");
  return *shown;
}

json turntableJson(const Turntable& t) {
  json views = json::array();
  for (const auto& v : t.views) views.push_back({{"sha256", v.sha256}, {"azimuth", v.azimuthDegrees}, {"elevation", v.elevationDegrees}});
  return {{"azimuths", t.azimuths}, {"elevations", t.elevations}, {"start", {t.startAzimuth, t.startElevation}}, {"views", views}};
}

json pageOf(const TrialView& view, const TrialImages& images) {
  const tasks::Question& q = view.prepared.question;
  const tasks::AnswerForm& form = tasks::answerForm(q);
  const tasks::Widget widget = form.widget(q);
  json labels = json::array();
  for (const auto& p : widget.marks) labels.push_back({{"label", p.label}, {"x", p.pixel.x}, {"y", p.pixel.y}});
  json page{{"kind", "trial"},
            {"phase", phaseName(view.plan.phase)},
            {"index", view.index},
            {"total", view.total},
            {"question", q.text},
            {"answer_kind", form.name()},
            {"format", form.format()},
            {"widget", widgetJson(widget)},
            {"limit_s", view.limitSeconds},
            {"image", {{"sha256", view.prepared.stimulusSha256}, {"width", view.plan.stimulus.width}, {"height", view.plan.stimulus.height}}},
            {"labels", labels}};
  if (view.prepared.floorPlan && !images.floorPlanSha256.empty())
    page["floor_plan"] = {{"sha256", images.floorPlanSha256}, {"width", view.prepared.floorPlan->width}, {"height", view.prepared.floorPlan->height}};
  if (images.turntable) page["turntable"] = turntableJson(*images.turntable);
  if (images.live) page["live"] = {{"navigation", navigationName(view.plan.navigation)}, {"lens", lensFollowsCursor(view.plan.stimulus)}};
  return page;
}

Checked checkTrialReply(const AnswerContext& context, const std::optional<Turntable>& turntable, const json& body) {
  if (!body.is_object()) return {"reply: expected a JSON object", {}};
  const std::string type = body.value("type", "");
  try {
    if (type == "onset") return {"", {type, {{"painted_ms", milliseconds(body, "painted_ms")}, {"shown", shownSize(body)}}}};
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
  } catch (const tasks::AnswerFormatError& e) {  // a participant's answer refused: said in their words too
    nlohmann::json refusal;
    if (!e.key().empty()) refusal = {{"key", e.key()}, {"args", e.args()}};
    return {type + ": " + e.what(), {}, refusal};
  } catch (const std::exception& e) {  // json type errors included
    return {std::string(type.empty() ? "reply" : type) + ": " + e.what(), {}, nullptr};
  }
  return {"unknown reply type '" + type.substr(0, 40) + "' (expected onset, view, answer or timeout)", {}};
}

}  // namespace

std::string answerText(const AnswerContext& context, const nlohmann::json& answer) {
  const tasks::AnswerForm& form = tasks::answerForm(context.question);
  try {  // the form writes the text and its own parser agrees
    return form.fromInput(context.question, widgetInput(form.widget(context.question), context.floorPlan, answer));
  } catch (const tasks::AnswerFormatError& e) {  // said once: the reply's type prefixes it
    const std::string message = e.what();
    throw tasks::AnswerFormatError(message.rfind("answer: ", 0) == 0 ? message.substr(8) : message, e.key(), e.args());
  }
}

Screen trialScreen(const TrialView& view, const TrialImages& images) {
  Screen s;
  s.page = pageOf(view, images);
  s.images.insert(view.prepared.stimulusSha256);
  if (!images.floorPlanSha256.empty()) s.images.insert(images.floorPlanSha256);
  if (images.turntable)
    for (const auto& v : images.turntable->views) s.images.insert(v.sha256);
  if (images.live && view.prepared.scene)
    s.live = std::make_shared<const LiveTrial>(LiveTrial{view.prepared.scene, view.plan.stimulus, view.plan.navigation, view.prepared.camera});
  // Copies: a late reply may be checked after the runner's view has gone.
  s.check = [context = AnswerContext{view.prepared.question, view.prepared.floorPlan}, turntable = images.turntable](const json& body) {
    return checkTrialReply(context, turntable, body);
  };
  return s;
}

}  // namespace tlab::study
