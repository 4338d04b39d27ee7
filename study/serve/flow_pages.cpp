#include "study/serve/flow_pages.hpp"

#include <algorithm>
#include <cmath>

#include "study/design/form_field.hpp"

namespace tlab::study {

namespace {

using nlohmann::json;

// A screen whose only reply is a button press ({"type": "continue"}).
Screen continueScreen(json page) {
  Screen s;
  s.page = std::move(page);
  s.check = [](const json& body) -> Checked {
    if (!body.is_object() || body.value("type", "") != "continue") return {"expected {\"type\": \"continue\"}", {}};
    return {"", {"continue", json::object()}};
  };
  return s;
}

json fieldJson(const FormField& f) {
  json j{{"id", f.id}, {"text", f.text}, {"kind", fieldKindName(f.kind)}, {"required", f.required}};
  switch (f.kind) {
    case FieldKind::Likert: j.update({{"points", f.points}, {"low", f.lowAnchor}, {"high", f.highAnchor}}); break;
    case FieldKind::Choice: j["options"] = f.options; break;
    case FieldKind::Number: j.update({{"min", f.minimum}, {"max", f.maximum}, {"integer", f.integer}}); break;
    case FieldKind::Text: break;
  }
  return j;
}

Checked checkForm(const std::vector<FormField>& fields, const ParticipantTexts& words, const json& body) {
  if (!body.is_object() || body.value("type", "") != "form") return {"expected {\"type\": \"form\", \"values\": [...]}", {}};
  const auto values = body.find("values");
  if (values == body.end() || !values->is_array() || values->size() != fields.size())
    return {"expected 'values': one text per field (" + std::to_string(fields.size()) + ")", {}};
  json texts = json::array();
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const json& v = (*values)[i];
    if (!v.is_string() || v.get<std::string>().size() > 2000) return {"field '" + fields[i].id + "': expected a text of at most 2000 bytes", {}};
    if (const std::string error = fieldError(fields[i], v.get<std::string>(), words); !error.empty()) return {"field '" + fields[i].id + "': " + error, {}};
    texts.push_back(v);
  }
  return {"", {"form", texts}};
}

}  // namespace

Screen messageScreen(const std::string& title, const std::string& text) {
  return continueScreen({{"kind", "message"}, {"title", title}, {"text", text}});
}

Screen consentScreen(const std::string& title, const ConsentSpec& consent) {
  Screen s;
  s.page = {{"kind", "consent"}, {"title", title}, {"text", consent.text}, {"accept", consent.accept}, {"decline", consent.decline}};
  s.check = [](const json& body) -> Checked {
    if (!body.is_object() || body.value("type", "") != "consent" || !body.contains("accepted") || !body["accepted"].is_boolean())
      return {"expected {\"type\": \"consent\", \"accepted\": true|false}", {}};
    return {"", {"consent", body["accepted"]}};
  };
  return s;
}

Screen formScreen(const std::string& title, const std::vector<FormField>& fields, const ParticipantTexts& texts) {
  Screen s;
  json items = json::array();
  for (const auto& f : fields) items.push_back(fieldJson(f));
  s.page = {{"kind", "form"}, {"title", title}, {"fields", items}};
  s.check = [fields, texts](const json& body) { return checkForm(fields, texts, body); };
  return s;
}

Screen feedbackScreen(const TrialView& view, const Feedback& feedback) {
  Screen s = continueScreen({{"kind", "feedback"},
                             {"correct", feedback.correct},
                             {"right_answer", feedback.rightAnswer},
                             {"given", feedback.given ? json(*feedback.given) : json()},
                             {"image", {{"sha256", view.prepared.stimulusSha256}, {"width", view.plan.stimulus.width}, {"height", view.plan.stimulus.height}}}});
  s.images.insert(view.prepared.stimulusSha256);
  return s;
}

Screen breakScreen(const BreakSpec& spec) { return continueScreen({{"kind", "break"}, {"text", spec.text}, {"min_seconds", spec.minSeconds}}); }

Screen endScreen(const std::string& title, const std::string& text, const std::string& completionCode, const std::string& completionUrl) {
  Screen s;
  s.page = {{"kind", "end"}, {"title", title}, {"text", text}, {"completion_code", completionCode}, {"completion_url", completionUrl}};
  return s;
}

std::optional<json> deviceRefusal(const Experiment& e, const json& display) {
  const std::string device = display.value("device", "desktop");
  if (std::find(e.online.devices.begin(), e.online.devices.end(), device) != e.online.devices.end()) return std::nullopt;
  const ParticipantTexts& t = e.texts;
  return json{{"kind", "end"}, {"seq", 0}, {"refused", device},
              {"title", t.text("device.refused_title")},
              {"text", t.text(device == "phone" ? "device.phone" : device == "tablet" ? "device.tablet" : "device.desktop")}};
}

Screen calibrationScreen(bool noCard) {
  Screen s;
  s.page = {{"kind", "calibration"}, {"no_card", noCard}};
  s.check = [noCard](const json& body) -> Checked {
    const auto number = [&](const char* key) { return body.contains(key) && body[key].is_number() ? body[key].get<double>() : -1.0; };
    if (!body.is_object() || body.value("type", "") != "calibration" || !body.contains("skipped") || !body["skipped"].is_boolean())
      return {"expected {\"type\": \"calibration\", \"skipped\": true|false, ...}", {}};
    const double adjustments = number("adjustments"), pxPerCm = number("px_per_cm"), card = number("card_css_px"), ratio = number("device_pixel_ratio");
    if (adjustments < 0 || adjustments > 1e6 || adjustments != std::floor(adjustments)) return {"calibration: 'adjustments' must be a count", {}};
    if (body["skipped"].get<bool>()) {
      if (!noCard) return {"calibration: this study has no \"I have no card\"", {}};
      return {"", {"calibration", {{"skipped", true}, {"px_per_cm", nullptr}, {"adjustments", adjustments}}}};
    }
    if (adjustments < 1) return {"calibration: the card's rectangle was not adjusted", {}};
    if (!(pxPerCm >= 5 && pxPerCm <= 1000) || !(card > 0 && card < 10000) || !(ratio > 0 && ratio <= 10))
      return {"calibration: expected 'px_per_cm' in [5, 1000], 'card_css_px' and 'device_pixel_ratio'", {}};
    return {"", {"calibration", {{"skipped", false}, {"px_per_cm", pxPerCm}, {"card_css_px", card}, {"device_pixel_ratio", ratio}, {"adjustments", adjustments}}}};
  };
  return s;
}

Screen waitScreen() {
  Screen s;
  s.page = {{"kind", "wait"}};
  return s;
}

}  // namespace tlab::study
