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

namespace {

std::vector<std::string> experimentIds(SessionStore& store) {
  Statement s = store.database().prepare("SELECT experiment_id FROM experiments GROUP BY experiment_id ORDER BY min(id)");
  std::vector<std::string> ids;
  while (s.step()) ids.push_back(s.text(0));
  return ids;
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& i : items) out += (out.empty() ? "" : ", ") + i;
  return out;
}

std::vector<StoredVersion> storedVersions(SessionStore& store, const std::string& experimentId) {
  std::vector<StoredVersion> all;
  for (auto& v : store.versions(experimentId)) {
    Statement count = store.database().prepare("SELECT count(*) FROM sessions WHERE experiment = ?1");
    count.bind(1, v.row);
    count.step();
    const Experiment e = parseExperiment(v.fileText, store.path() + ":" + v.filePath, StimulusChecks::Skip);
    all.push_back({v, designFingerprint(e), int(count.integer(0))});
  }
  std::vector<StoredVersion> withData;
  for (const auto& v : all)
    if (v.sessions > 0) withData.push_back(v);
  return withData.empty() ? all : withData;
}

}  // namespace

std::string StoredExperiment::describeVersions() const {
  std::string out;
  for (const auto& v : versions)
    out += (out.empty() ? "" : "; ") + std::string("version ") + std::to_string(v.version.version) + " (file " +
           v.version.sha256.substr(0, 8) + "…, design " + v.design.substr(0, 8) + "…, " + std::to_string(v.sessions) + " sessions)";
  return out;
}

StoredExperiment storedExperiment(SessionStore& store, const std::string& experimentId, bool poolVersions) {
  const auto ids = experimentIds(store);
  if (ids.empty()) throw StoreError(store.path() + ": no experiment has been run into this database yet");
  std::string id = experimentId;
  if (id.empty() && ids.size() > 1)
    throw StoreError(store.path() + " holds several experiments (" + joined(ids) + "); choose one with --experiment");
  if (id.empty()) id = ids.front();
  if (std::find(ids.begin(), ids.end(), id) == ids.end())
    throw StoreError(store.path() + ": no experiment '" + id + "' (it holds " + joined(ids) + ")");
  StoredExperiment stored;
  stored.versions = storedVersions(store, id);
  const auto& newest = stored.versions.back().version;
  stored.row = newest.row;
  stored.experiment = parseExperiment(newest.fileText, store.path() + ":" + newest.filePath, StimulusChecks::Skip);
  for (const auto& v : stored.versions)
    if (v.design != stored.versions.front().design && !poolVersions)
      throw StoreError(store.path() + ": the data of experiment '" + id + "' come from versions whose designs differ (" +
                       stored.describeVersions() + "); pool them anyway with --pool-versions");
  return stored;
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
  analysis::Table table(store.path(), names);
  Statement s = store.database().prepare(
      "SELECT p.participant, t.levels_json, t.task_id, t.block, " + column->second + ", t.id FROM trials t "
      "JOIN participants p ON p.id = t.participant JOIN responses r ON r.trial = t.id "
      "JOIN experiments x ON x.id = p.experiment WHERE x.experiment_id = ?1 AND p.status != 'dropped' AND t.phase = 'test' AND " + column->second + " IS NOT NULL "
      "ORDER BY p.id, t.sequence");
  s.bind(1, e.id);
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
