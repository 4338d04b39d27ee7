#include "study/study_record_tables.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>

#include "analysis/likert_summary.hpp"
#include "study/simulated_observer.hpp"

namespace tlab::study {

ParticipantModes participantModes(SessionStore& store, const StoredExperiment& stored) {
  Statement s = store.database().prepare(
      "SELECT SUM(s.mode = 'simulated'), COUNT(*) FROM sessions s JOIN participants p ON p.id = s.participant "
      "WHERE p.experiment = ?1 GROUP BY p.id");
  s.bind(1, stored.row);
  ParticipantModes modes;
  while (s.step()) {
    ++modes.participants;
    const std::int64_t simulated = s.integer(0), sessions = s.integer(1);
    if (simulated == sessions) ++modes.simulated;
    else if (simulated > 0) ++modes.mixed;
  }
  return modes;
}

std::string simulatedDataWarning(const ParticipantModes& modes, const ObserverParams& observer) {
  if (modes.simulated == 0 && modes.mixed == 0) return "";
  const std::string who = modes.simulated == modes.participants
                              ? "All " + std::to_string(modes.participants) + " participants"
                              : std::to_string(modes.simulated + modes.mixed) + " of " +
                                    std::to_string(modes.participants) + " participants";
  return "SIMULATED DATA: " + who + " in this report are simulated observers (tlab simulate), not people. " +
         describeSimulatedObserver(observer);
}

std::vector<analysis::TextTable> questionnaireTables(SessionStore& store, const StoredExperiment& stored) {
  std::vector<analysis::TextTable> tables;
  for (const Questionnaire& q : stored.experiment.questionnaires) {
    analysis::Table answers(store.database().path(), {"questionnaire", "item", "value"});
    Statement s = store.database().prepare(
        "SELECT a.item, a.value, a.id FROM questionnaire_answers a JOIN participants p ON p.id = a.participant "
        "WHERE p.experiment = ?1 AND p.status != 'dropped' AND a.questionnaire = ?2 ORDER BY a.id");
    s.bind(1, stored.row).bind(2, q.id);
    std::vector<std::vector<std::string>> rows;
    while (s.step()) rows.push_back({s.text(0), std::to_string(s.integer(1)), std::to_string(s.integer(2))});
    // Items in the order of the experiment file, each with its text.
    for (const LikertItem& item : q.items)
      for (const auto& r : rows)
        if (r[0] == item.id) answers.addRow({q.id, item.id + ": " + item.text, r[1]}, std::stoull(r[2]));
    if (answers.rowCount() == 0) continue;
    tables.push_back(analysis::likertTable(analysis::summarizeLikert(answers, "questionnaire", "item", "value", q.points),
                                           q.points,
                                           "Questionnaire '" + q.id + "' (" + q.when + "; 1 = " + q.lowAnchor + ", " +
                                               std::to_string(q.points) + " = " + q.highAnchor + ")"));
  }
  return tables;
}

analysis::TextTable stimulusTable(SessionStore& store, const StoredExperiment& stored) {
  analysis::TextTable t;
  t.caption = "Stimuli shown (files under the database's stimulus folder; SHA-256 of each picture)";
  t.header = {"condition", "task", "phase", "stimulus", "file", "sha256", "trials", "participants"};
  Statement s = store.database().prepare(
      "SELECT t.condition, t.task_id, t.phase, t.stimulus_key, t.stimulus_path, t.stimulus_sha256, COUNT(*), "
      "COUNT(DISTINCT t.participant) FROM trials t JOIN participants p ON p.id = t.participant "
      "WHERE p.experiment = ?1 GROUP BY t.stimulus_sha256, t.stimulus_key, t.phase, t.condition, t.task_id "
      "ORDER BY t.phase DESC, t.condition, t.task_id, t.stimulus_key");
  s.bind(1, stored.row);
  while (s.step())
    t.rows.push_back({s.text(0), s.text(1), s.text(2), s.text(3), s.text(4), s.text(5).substr(0, 16),
                      std::to_string(s.integer(6)), std::to_string(s.integer(7))});
  return t;
}

std::vector<analysis::ReportImage> stimulusImages(SessionStore& store, const StoredExperiment& stored, std::size_t limit) {
  const std::filesystem::path folder = std::filesystem::path(store.database().path()).parent_path();
  Statement s = store.database().prepare(
      "SELECT t.condition, t.task_id, t.stimulus_path, MIN(t.id) FROM trials t JOIN participants p ON p.id = t.participant "
      "WHERE p.experiment = ?1 AND t.phase = 'test' GROUP BY t.condition, t.task_id ORDER BY t.condition, t.task_id");
  s.bind(1, stored.row);
  std::vector<analysis::ReportImage> images;
  while (s.step() && images.size() < limit) {
    std::ifstream file(folder / s.text(2), std::ios::binary);
    if (!file) continue;
    images.push_back({s.text(1) + ": " + s.text(0), "image/png",
                      std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>())});
  }
  return images;
}

void appendStudyRecord(analysis::Report& report, SessionStore& store, const StoredExperiment& stored) {
  for (auto& table : questionnaireTables(store, stored)) report.appendices.push_back(std::move(table));
  report.appendices.push_back(stimulusTable(store, stored));
  for (auto& image : stimulusImages(store, stored)) report.images.push_back(std::move(image));
}

}  // namespace tlab::study
