#include "tasks/question_json.hpp"

namespace tlab::tasks {

nlohmann::json groundTruthJson(const GroundTruth& truth) {
  return std::visit(
      [](const auto& v) -> nlohmann::json {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, glm::dvec2>) return nlohmann::json::array({v.x, v.y});
        else if constexpr (std::is_same_v<T, glm::dvec3>) return nlohmann::json::array({v.x, v.y, v.z});
        else return nlohmann::json(v);
      },
      truth);
}

nlohmann::json toJson(const Question& q) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& p : q.points)
    points.push_back({{"label", p.label}, {"role", p.role}, {"object", p.object},
                      {"world", {p.world.x, p.world.y, p.world.z}}, {"pixel", {p.pixel.x, p.pixel.y}},
                      {"pixel_index", {int(std::floor(p.pixel.x)), int(std::floor(p.pixel.y))}}});
  nlohmann::json checks = nlohmann::json::array();
  for (const auto& c : q.checks) checks.push_back({{"rule", c.rule}, {"value", c.value}, {"required", c.required}});
  nlohmann::json measurements = nlohmann::json::object();
  for (const auto& [k, v] : q.measurements) measurements[k] = v;
  nlohmann::json j = {{"task", q.task},
                      {"number", q.number},
                      {"text", q.text},
                      {"answer_kind", answerKindName(q.answerKind)},
                      {"answer_format", answerFormat(q.answerKind)},
                      {"time_limit_s", q.timeLimitSeconds},
                      {"points", points},
                      {"truth", groundTruthJson(q.truth)},
                      {"checks", checks},
                      {"measurements", measurements}};
  if (q.correctWithin > 0.0) j["correct_within"] = q.correctWithin;
  if (!q.directions.empty()) {
    nlohmann::json directions = nlohmann::json::object();
    for (const auto& [k, d] : q.directions) directions[k] = {d.x, d.y, d.z};
    j["directions"] = directions;
  }
  return j;
}

nlohmann::json toJson(const Score& s) {
  nlohmann::json j = {{"answered", s.answered}, {"correct", s.correct}, {"score", s.value}, {"raw_answer", s.rawAnswer}};
  j["partial_credit"] = s.partialCredit ? nlohmann::json(*s.partialCredit) : nlohmann::json();
  j["error"] = s.error ? nlohmann::json(*s.error) : nlohmann::json();
  for (const auto& [k, v] : s.measures) j[k] = v;
  if (!s.note.empty()) j["note"] = s.note;
  return j;
}

}  // namespace tlab::tasks
