// What a report of a study database shows besides the tests, read through the Store: who the
// participants were, their information and questionnaire answers (Likert items: the ordinal
// summary; choices: counts; numbers: descriptives; free text: listed), and the stimuli shown.
#include "study/analyze/study_record_tables.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "analysis/descriptives.hpp"
#include "analysis/likert_summary.hpp"
#include "analysis/number_format.hpp"
#include "study/analyze/replay_listing.hpp"
#include "study/run/simulated_observer.hpp"
#include "study/store/timing_tables.hpp"

namespace tlab::study {

namespace {

std::vector<StoredAnswer> answersOf(const std::vector<StoredAnswer>& all, const std::string& form, const std::string& field) {
  std::vector<StoredAnswer> out;
  for (const auto& a : all)
    if (a.form == form && a.field == field) out.push_back(a);
  return out;
}

analysis::TextTable choiceTable(const FormField& f, const std::vector<StoredAnswer>& answers, const std::string& caption) {
  analysis::TextTable t;
  t.caption = caption + ": " + f.text;
  t.header = {"choice", "n", "share"};
  for (const auto& option : f.options) {
    std::size_t n = 0;
    for (const auto& a : answers) n += a.value == option ? 1 : 0;
    t.rows.push_back({option, std::to_string(n), answers.empty() ? "" : analysis::formatNumber(double(n) / double(answers.size()), 3)});
  }
  return t;
}

std::vector<std::string> numberRow(const FormField& f, const std::vector<StoredAnswer>& answers) {
  std::vector<double> xs;
  for (const auto& a : answers)
    if (a.number) xs.push_back(*a.number);
  if (xs.empty()) return {f.id + ": " + f.text, "0", "", "", "", ""};
  if (xs.size() == 1) {  // a pilot's one answer: no spread to estimate
    const std::string x = analysis::formatNumber(xs.front(), 3);
    return {f.id + ": " + f.text, "1", x, "", x, x};
  }
  const analysis::Descriptives d = analysis::describe(xs, f.id);
  return {f.id + ": " + f.text, std::to_string(d.n), analysis::formatNumber(d.mean, 3), analysis::formatNumber(d.sd, 3),
          analysis::formatNumber(d.min, 3), analysis::formatNumber(d.max, 3)};
}

// The tables of one form: Likert items together, then one table per choice item, the number
// items' descriptives, and the free-text answers listed.
std::vector<analysis::TextTable> formTables(const std::string& form, const std::string& caption, const std::vector<FormField>& fields,
                                            const std::vector<StoredAnswer>& all, const std::string& source) {
  std::vector<analysis::TextTable> tables;
  std::map<int, analysis::Table> likert;  // by number of points
  analysis::TextTable numbers{caption + ": numbers", {"item", "n", "mean", "sd", "min", "max"}, {}};
  analysis::TextTable texts{caption + ": free text", {"participant", "item", "answer"}, {}};
  for (const auto& f : fields) {
    const auto answers = answersOf(all, form, f.id);
    if (f.kind == FieldKind::Likert) {
      auto [it, added] = likert.try_emplace(f.points, analysis::Table(source, {"form", "item", "value"}));
      for (const auto& a : answers)
        if (a.number) it->second.addRow({form, f.id + ": " + f.text, std::to_string(int(*a.number))}, a.sourceRow);
    } else if (f.kind == FieldKind::Choice && !answers.empty()) {
      tables.push_back(choiceTable(f, answers, caption));
    } else if (f.kind == FieldKind::Number && !answers.empty()) {
      numbers.rows.push_back(numberRow(f, answers));
    } else if (f.kind == FieldKind::Text) {
      for (const auto& a : answers)
        if (!a.value.empty()) texts.rows.push_back({a.participant, f.id, a.value});
    }
  }
  for (const auto& [points, table] : likert) {
    if (table.rowCount() == 0) continue;
    const FormField* first = nullptr;
    for (const auto& f : fields)
      if (f.kind == FieldKind::Likert && f.points == points && !first) first = &f;
    tables.insert(tables.begin(), analysis::likertTable(analysis::summarizeLikert(table, "form", "item", "value", points), points,
                                                        caption + " (1 = " + first->lowAnchor + ", " + std::to_string(points) + " = " +
                                                            first->highAnchor + ")"));
  }
  if (!numbers.rows.empty()) tables.push_back(numbers);
  if (!texts.rows.empty()) tables.push_back(texts);
  return tables;
}

}  // namespace

ParticipantModes participantModes(Store& store, const StoredExperiment& stored) {
  ParticipantModes modes;
  for (const auto& byMode : store.sessionModes(stored.experiment.id)) {
    ++modes.participants;
    int sessions = 0;
    for (const auto& [mode, n] : byMode) sessions += n;
    const int simulated = byMode.count("simulated") ? byMode.at("simulated") : 0;
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

std::vector<analysis::TextTable> questionnaireTables(Store& store, const StoredExperiment& stored) {
  const auto all = store.formAnswers(stored.experiment.id);
  std::vector<analysis::TextTable> tables;
  for (auto& t : formTables("info", "Participant information", stored.experiment.info, all, store.location())) tables.push_back(t);
  for (const Questionnaire& q : stored.experiment.questionnaires)
    for (auto& t : formTables(q.id, "Questionnaire '" + q.id + "' (" + q.when + ")", q.items, all, store.location())) tables.push_back(t);
  return tables;
}

analysis::TextTable stimulusTable(Store& store, const StoredExperiment& stored) {
  analysis::TextTable t;
  t.caption = "Stimuli shown (files under the database's stimulus folder; SHA-256 of each picture)";
  const DataTable d = store.stimulusSummary(stored.experiment.id);
  t.header = d.header;
  for (auto row : d.rows) {
    row[5] = row[5].substr(0, 16);
    t.rows.push_back(row);
  }
  return t;
}

std::vector<analysis::ReportImage> stimulusImages(Store& store, const StoredExperiment& stored, std::size_t limit) {
  const std::filesystem::path folder = std::filesystem::path(store.location()).parent_path();
  std::vector<analysis::ReportImage> images;
  for (const auto& row : store.stimulusExamples(stored.experiment.id).rows) {
    if (images.size() >= limit) break;
    std::ifstream file(folder / row[2], std::ios::binary);
    if (!file) continue;
    images.push_back({row[1] + ": " + row[0], "image/png", std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>())});
  }
  return images;
}

void appendStudyRecord(analysis::Report& report, Store& store, const StoredExperiment& stored, const ReplayLinks& replays) {
  for (auto& table : questionnaireTables(store, stored)) report.appendices.push_back(std::move(table));
  report.appendices.push_back(stimulusTable(store, stored));
  report.appendices.push_back(sessionTimingTable(store, stored));
  if (analysis::TextTable table = replayTable(store, store.location(), stored.experiment.id, replays); !table.rows.empty())
    report.appendices.push_back(std::move(table));
  for (auto& image : stimulusImages(store, stored)) report.images.push_back(std::move(image));
}

}  // namespace tlab::study
