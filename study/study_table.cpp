#include "study/study_table.hpp"

#include <algorithm>
#include <map>

#include <nlohmann/json.hpp>

#include "study/experiment_file.hpp"

namespace tlab::study {

namespace {

const std::map<std::string, std::string> kDependentVariableSql = {
    {"correct", "r.correct"}, {"score", "r.score"},           {"rt", "r.rt_seconds"},
    {"error", "r.error"},     {"partial_credit", "r.partial_credit"}, {"answered", "r.answered"}};

}  // namespace

StoredExperiment storedExperiment(SessionStore& store, const std::string& experimentId) {
  Statement s = store.database().prepare("SELECT id, experiment_id, file_path, file_text FROM experiments ORDER BY id");
  std::vector<std::tuple<std::int64_t, std::string, std::string, std::string>> rows;
  while (s.step()) rows.emplace_back(s.integer(0), s.text(1), s.text(2), s.text(3));
  std::string ids;
  for (const auto& r : rows) ids += (ids.empty() ? "" : ", ") + std::get<1>(r);
  if (rows.empty()) throw StoreError(store.database().path() + ": no experiment has been run into this database yet");
  for (auto it = rows.rbegin(); it != rows.rend(); ++it) {
    if (!experimentId.empty() && std::get<1>(*it) != experimentId) continue;
    if (experimentId.empty() && rows.size() > 1 && std::get<1>(rows.front()) != std::get<1>(rows.back()))
      throw StoreError(store.database().path() + " holds several experiments (" + ids + "); choose one with --experiment");
    return {std::get<0>(*it), parseExperiment(std::get<3>(*it), store.database().path() + ":" + std::get<2>(*it))};
  }
  throw StoreError(store.database().path() + ": no experiment '" + experimentId + "' (it holds " + ids + ")");
}

analysis::AnalysisPlan analysisPlan(const AnalysisSpec& spec, const std::string& dv) {
  analysis::AnalysisPlan plan;
  plan.title = spec.title;
  plan.dependentVariables = {dv};
  plan.within = spec.within;
  plan.between = spec.between;
  plan.subject = "participant";
  plan.tests.clear();
  for (const auto& t : spec.tests) {
    if (t == "anova") plan.tests.push_back(analysis::PlannedTest::Anova);
    if (t == "t-tests") plan.tests.push_back(analysis::PlannedTest::TTests);
    if (t == "rank-tests") plan.tests.push_back(analysis::PlannedTest::RankTests);
  }
  plan.confidence = 1.0 - spec.alpha;
  return plan;
}

analysis::Table analysisTable(SessionStore& store, const StoredExperiment& stored, const AnalysisSpec& spec, const std::string& dv) {
  const auto column = kDependentVariableSql.find(dv);
  if (column == kDependentVariableSql.end()) throw StoreError("unknown dependent variable '" + dv + "'");
  const Experiment& e = stored.experiment;
  std::vector<std::string> names = {"participant"};
  for (const auto& f : e.factors) names.push_back(f.name);
  names.insert(names.end(), {"task", "block", dv});
  analysis::Table table(store.database().path(), names);
  Statement s = store.database().prepare(
      "SELECT p.participant, t.levels_json, t.task_id, t.block, " + column->second + ", t.id FROM trials t "
      "JOIN participants p ON p.id = t.participant JOIN responses r ON r.trial = t.id "
      "WHERE p.experiment = ?1 AND p.status != 'dropped' AND t.phase = 'test' AND " + column->second + " IS NOT NULL "
      "ORDER BY p.id, t.sequence");
  s.bind(1, stored.row);
  while (s.step()) {
    const std::string taskId = s.text(2);
    if (!spec.tasks.empty() && std::find(spec.tasks.begin(), spec.tasks.end(), taskId) == spec.tasks.end()) continue;
    const auto levels = nlohmann::json::parse(s.text(1));
    std::vector<std::string> cells = {s.text(0)};
    for (const auto& f : e.factors) cells.push_back(levels.value(f.name, std::string()));
    cells.push_back(taskId);
    cells.push_back(std::to_string(s.integer(3)));
    char value[64];
    std::snprintf(value, sizeof value, "%.17g", s.real(4));
    cells.push_back(value);
    table.addRow(std::move(cells), std::size_t(s.integer(5)));
  }
  return table;
}

}  // namespace tlab::study
