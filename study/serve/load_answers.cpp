#include "study/serve/load_answers.hpp"

#include <cmath>
#include <cstdio>

namespace tlab::study {

namespace {

using nlohmann::json;

int uniform(std::mt19937_64& rng, int low, int high) { return std::uniform_int_distribution<int>(low, high)(rng); }

// A label-set answer: a non-empty random subset of the labels, in the order offered.
json labelSubset(const json& labels, std::mt19937_64& rng) {
  json chosen = json::array();
  for (const auto& l : labels)
    if (uniform(rng, 0, 1) == 1) chosen.push_back(l.at("label"));
  if (chosen.empty()) chosen.push_back(labels.at(std::size_t(uniform(rng, 0, int(labels.size()) - 1))).at("label"));
  return chosen;
}

// A valid answer for the page's widget (the load tester answers widgets as a page would).
std::optional<json> answerFor(const json& page, std::mt19937_64& rng) {
  const json widget = page.value("widget", json::object());
  const std::string kind = widget.value("kind", "");
  const json labels = page.value("labels", json::array());
  if (kind == "number") return uniform(rng, std::max(1, widget.value("min", 1)), 5);
  if (kind == "pick-label" && !labels.empty()) return labels.at(std::size_t(uniform(rng, 0, int(labels.size()) - 1))).at("label");
  if (kind == "pick-labels") return labels.empty() ? json::array() : labelSubset(labels, rng);  // [] is "none"
  if (kind == "buttons" && !widget.value("buttons", json::array()).empty())
    return widget["buttons"].at(std::size_t(uniform(rng, 0, int(widget["buttons"].size()) - 1)));
  if (kind == "floor-plan" && page.contains("floor_plan")) {
    const json& plan = page["floor_plan"];
    // Pixel centres: strictly inside the plan however the page scales it.
    return json{{"x", uniform(rng, 0, plan.value("width", 1) - 1) + 0.5}, {"y", uniform(rng, 0, plan.value("height", 1) - 1) + 0.5}};
  }
  if (kind == "gauge") return json{{"slant", uniform(rng, 0, 80)}, {"tilt", uniform(rng, 0, 359)}};
  return std::nullopt;
}

std::string fieldValue(const json& field, std::mt19937_64& rng) {
  const std::string kind = field.value("kind", "");
  if (kind == "likert") return std::to_string(uniform(rng, 1, std::max(1, field.value("points", 1))));
  if (kind == "choice" && !field.value("options", json::array()).empty()) {
    const json& options = field["options"];
    return options.at(std::size_t(uniform(rng, 0, int(options.size()) - 1))).get<std::string>();
  }
  if (kind == "number") {
    const double low = field.value("min", 0.0), high = field.value("max", 0.0);
    const double v = field.value("integer", false) ? std::ceil(low) + std::floor((std::floor(high) - std::ceil(low)) / 2.0) : (low + high) / 2.0;
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
  }
  return "load test";
}

}  // namespace

json loadAnswer(const json& trialPage, double rtMs, std::mt19937_64& rng) {
  const auto answer = answerFor(trialPage, rng);
  if (!answer) return {{"type", "timeout"}};
  return {{"type", "answer"}, {"answer", *answer}, {"rt_ms", rtMs}};
}

json loadFormValues(const json& formPage, std::mt19937_64& rng) {
  json values = json::array();
  for (const auto& field : formPage.value("fields", json::array())) values.push_back(fieldValue(field, rng));
  return {{"type", "form"}, {"values", values}};
}

std::vector<std::string> pageImages(const json& page) {
  std::vector<std::string> out;
  auto add = [&out](const json& holder) {
    if (holder.is_object() && holder.contains("sha256") && holder["sha256"].is_string()) out.push_back(holder["sha256"].get<std::string>());
  };
  add(page.value("image", json()));
  add(page.value("floor_plan", json()));
  if (page.contains("turntable") && page["turntable"].is_object())
    for (const auto& v : page["turntable"].value("views", json::array())) add(v);
  return out;
}

}  // namespace tlab::study
