#include "study/store/study_table.hpp"

#include <algorithm>
#include <map>

#include <nlohmann/json.hpp>

#include "study/design/experiment_file.hpp"

namespace tlab::study {

namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& i : items) out += (out.empty() ? "" : ", ") + i;
  return out;
}

std::vector<StoredVersion> storedVersions(Store& store, const std::string& experimentId) {
  std::vector<StoredVersion> all;
  for (auto& v : store.versions(experimentId)) {
    const Experiment e = parseExperiment(v.fileText, store.location() + ":" + v.filePath, StimulusChecks::Skip);
    all.push_back({v, designFingerprint(e), store.sessionCount(v.row)});
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

StoredExperiment storedExperiment(Store& store, const std::string& experimentId, bool poolVersions) {
  const auto ids = store.experimentIds();
  if (ids.empty()) throw StoreError(store.location() + ": no experiment has been run into this database yet");
  std::string id = experimentId;
  if (id.empty() && ids.size() > 1)
    throw StoreError(store.location() + " holds several experiments (" + joined(ids) + "); choose one with --experiment");
  if (id.empty()) id = ids.front();
  if (std::find(ids.begin(), ids.end(), id) == ids.end())
    throw StoreError(store.location() + ": no experiment '" + id + "' (it holds " + joined(ids) + ")");
  StoredExperiment stored;
  stored.versions = storedVersions(store, id);
  const auto& newest = stored.versions.back().version;
  stored.row = newest.row;
  stored.experiment = parseExperiment(newest.fileText, store.location() + ":" + newest.filePath, StimulusChecks::Skip);
  for (const auto& v : stored.versions)
    if (v.design != stored.versions.front().design && !poolVersions)
      throw StoreError(store.location() + ": the data of experiment '" + id + "' come from versions whose designs differ (" +
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

analysis::Table analysisTable(Store& store, const StoredExperiment& stored, const AnalysisSpec& spec, const std::string& dv) {
  const Experiment& e = stored.experiment;
  std::vector<std::string> names = {"participant"};
  for (const auto& f : e.factors) names.push_back(f.name);
  names.insert(names.end(), {"task", "block", "stimulus", dv});
  analysis::Table table(store.location(), names);
  for (const auto& r : store.analysisRecords(e.id, dv)) {
    if (!spec.tasks.empty() && std::find(spec.tasks.begin(), spec.tasks.end(), r.taskId) == spec.tasks.end()) continue;
    const auto levels = nlohmann::json::parse(r.levelsJson);
    std::vector<std::string> cells = {r.participant};
    for (const auto& f : e.factors) cells.push_back(levels.value(f.name, std::string()));
    cells.push_back(r.taskId);
    cells.push_back(std::to_string(r.block));
    cells.push_back(r.stimulusSha256);
    char value[64];
    std::snprintf(value, sizeof value, "%.17g", r.value);
    cells.push_back(value);
    table.addRow(std::move(cells), r.sourceRow);
  }
  return table;
}

}  // namespace tlab::study
