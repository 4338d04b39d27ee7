#include "study/session_store.hpp"

#include <chrono>
#include <ctime>

#include <sqlite3.h>
#include <unistd.h>

#include "renderer/image/sha256.hpp"
#include "study/schema_migrations.hpp"

namespace tlab::study {

namespace {



std::string blockOrderText(const Design& design, const SlotDesign& slot) {
  std::string text;
  for (std::size_t b = 0; b < slot.blocks.size(); ++b) text += (b ? " | " : "") + design.describe(slot.blocks[b]);
  return text;
}

}  // namespace

std::string stationName() {
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0) std::snprintf(host, sizeof host, "unknown");
  return std::string(host) + ":" + std::to_string(getpid());
}

std::string utcTimestamp() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t t = std::chrono::system_clock::to_time_t(now);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[80];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday, tm.tm_hour,
                tm.tm_min, tm.tm_sec, int(ms));
  return buf;
}

SessionStore::SessionStore(const std::string& path, bool create) : db_(path, create) {
  const int version = db_.userVersion();
  if (version > kSchemaVersion)
    throw StoreError(path + ": written by a newer tlab (schema version " + std::to_string(version) + "; this tlab reads up to " +
                     std::to_string(kSchemaVersion) + "): open it with that tlab or a newer one; nothing was changed");
  checkIntegrity();
  db_.execute("PRAGMA journal_mode=WAL");
  db_.execute("PRAGMA synchronous=FULL");
  db_.execute("PRAGMA foreign_keys=ON");
  if (version == 0) {
    // Tables first, then the version: a second process may just be creating the schema (one transaction).
    Statement tables = db_.prepare("SELECT count(*) FROM sqlite_master WHERE type = 'table'");
    if (tables.step() && tables.integer(0) > 0 && db_.userVersion() == 0)
      throw StoreError(path + ": not a tlab study database (it has other tables)");
  }
  try {
    migrateSchema(db_);
  } catch (const StoreError& e) {
    // A reader (analyze, export) may read an older but complete schema from a read-only file.
    if (create || version == 0 || (e.code() & 0xff) != SQLITE_READONLY) throw;
  }
}

void SessionStore::checkIntegrity() {
  Statement check = db_.prepare("PRAGMA quick_check(1)");
  if (check.step() && check.text(0) != "ok")
    throw StoreError(db_.path() + ": the database file is damaged (" + check.text(0) +
                         "); tlab does not write to it: restore it from a backup (or salvage with 'sqlite3 FILE .recover'), "
                         "then continue with --resume",
                     SQLITE_CORRUPT);
}

std::optional<std::int64_t> SessionStore::findExperiment(const std::string& experimentId) {
  Statement s = db_.prepare("SELECT id FROM experiments WHERE experiment_id = ?1 ORDER BY id DESC LIMIT 1");
  s.bind(1, experimentId);
  if (!s.step()) return std::nullopt;
  return s.integer(0);
}

std::int64_t SessionStore::registerExperiment(const Experiment& e, const std::string& tlabVersion) {
  const std::string hash = render::sha256Hex(e.text);
  Transaction t(db_);
  Statement same = db_.prepare("SELECT id FROM experiments WHERE sha256 = ?1");
  same.bind(1, hash);
  if (same.step()) return same.integer(0);
  Statement other = db_.prepare("SELECT sha256 FROM experiments WHERE experiment_id = ?1");
  other.bind(1, e.id);
  if (other.step())
    throw StoreError(db_.path() + " already holds experiment '" + e.id + "' from a different file (sha256 " +
                     other.text(0).substr(0, 12) + "…, this file " + hash.substr(0, 12) +
                     "…); use a new database or the original file");
  Statement insert = db_.prepare(
      "INSERT INTO experiments (experiment_id, file_path, file_text, sha256, tlab_version, created_at) VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
  insert.bind(1, e.id).bind(2, e.path).bind(3, e.text).bind(4, hash).bind(5, tlabVersion).bind(6, utcTimestamp());
  insert.run();
  const std::int64_t id = db_.lastInsertId();
  t.commit();
  return id;
}

std::optional<ParticipantRecord> SessionStore::findParticipant(std::int64_t experiment, const std::string& participant) {
  Statement s = db_.prepare("SELECT id, participant, slot, status FROM participants WHERE experiment = ?1 AND participant = ?2");
  s.bind(1, experiment).bind(2, participant);
  if (!s.step()) return std::nullopt;
  return ParticipantRecord{s.integer(0), s.text(1), int(s.integer(2)), s.text(3)};
}

ParticipantRecord SessionStore::enrol(std::int64_t experiment, const std::string& participant, const Design& design) {
  Transaction t(db_);
  Statement taken = db_.prepare("SELECT slot FROM assignments WHERE experiment = ?1 AND status != 'dropped' ORDER BY slot");
  taken.bind(1, experiment);
  int slot = 0;
  while (taken.step() && taken.integer(0) == slot) ++slot;
  Statement insert = db_.prepare(
      "INSERT INTO participants (experiment, participant, slot, status, created_at) VALUES (?1, ?2, ?3, 'active', ?4)");
  insert.bind(1, experiment).bind(2, participant).bind(3, slot).bind(4, utcTimestamp());
  try {
    insert.run();
  } catch (const StoreError& e) {
    if (e.code() != SQLITE_CONSTRAINT_UNIQUE) throw;
    throw StoreError(db_.path() + ": participant '" + participant + "' is already enrolled (by another station?)", e.code());
  }
  const std::int64_t id = db_.lastInsertId();
  const SlotDesign d = design.slot(slot);
  Statement assign = db_.prepare(
      "INSERT INTO assignments (experiment, slot, participant, design_row, between_cell, block_order, status, assigned_at) "
      "VALUES (?1, ?2, ?3, ?4, ?5, ?6, 'active', ?7)");
  assign.bind(1, experiment).bind(2, slot).bind(3, id).bind(4, d.row).bind(5, d.betweenCell).bind(6, blockOrderText(design, d));
  assign.bind(7, utcTimestamp());
  assign.run();
  t.commit();
  return ParticipantRecord{id, participant, slot, "active"};
}

void SessionStore::dropParticipant(std::int64_t experiment, const std::string& participant, const std::string& reason) {
  const auto p = findParticipant(experiment, participant);
  if (!p) throw StoreError(db_.path() + ": no participant '" + participant + "' in this experiment");
  if (p->status == "dropped") throw StoreError("participant '" + participant + "' has already dropped out");
  Transaction t(db_);
  Statement a = db_.prepare("UPDATE participants SET status = 'dropped' WHERE id = ?1");
  a.bind(1, p->id).run();
  Statement b = db_.prepare("UPDATE assignments SET status = 'dropped', note = ?2 WHERE participant = ?1");
  b.bind(1, p->id).bind(2, reason).run();
  t.commit();
}

void SessionStore::finishParticipant(std::int64_t participantId) {
  Transaction t(db_);
  Statement a = db_.prepare("UPDATE participants SET status = 'finished', finished_at = ?2 WHERE id = ?1");
  a.bind(1, participantId).bind(2, utcTimestamp()).run();
  Statement b = db_.prepare("UPDATE assignments SET status = 'finished' WHERE participant = ?1 AND status = 'active'");
  b.bind(1, participantId).run();
  t.commit();
}

std::vector<AssignmentRecord> SessionStore::assignments(std::int64_t experiment) {
  Statement s = db_.prepare(
      "SELECT a.slot, a.design_row, a.between_cell, p.participant, a.status, a.block_order FROM assignments a "
      "JOIN participants p ON p.id = a.participant WHERE a.experiment = ?1 ORDER BY a.slot, a.id");
  s.bind(1, experiment);
  std::vector<AssignmentRecord> out;
  while (s.step())
    out.push_back({int(s.integer(0)), int(s.integer(1)), int(s.integer(2)), s.text(3), s.text(4), s.text(5)});
  return out;
}

std::int64_t SessionStore::startSession(std::int64_t participantId, const std::string& mode) {
  Statement s = db_.prepare("INSERT INTO sessions (participant, mode, started_at, station) VALUES (?1, ?2, ?3, ?4)");
  s.bind(1, participantId).bind(2, mode).bind(3, utcTimestamp()).bind(4, stationName()).run();
  return db_.lastInsertId();
}

void SessionStore::endSession(std::int64_t session, const std::string& reason) {
  Statement s = db_.prepare("UPDATE sessions SET ended_at = ?2, end_reason = ?3 WHERE id = ?1");
  s.bind(1, session).bind(2, utcTimestamp()).bind(3, reason).run();
}

void SessionStore::insertTrials(std::int64_t participantId, const std::vector<TrialRecord>& trials) {
  Transaction t(db_);
  Statement s = db_.prepare(
      "INSERT INTO trials (participant, sequence, phase, block, condition, levels_json, task_id, task, trial, question, "
      "questions_in_trial, stimulus_key, probe_seed, question_json, answer_kind, truth_json, time_limit, trial_time_limit, "
      "stimulus_path, stimulus_sha256) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17, ?18, ?19, ?20)");
  for (const auto& r : trials) {
    s.bind(1, participantId).bind(2, r.sequence).bind(3, r.phase).bind(4, r.block).bind(5, r.condition).bind(6, r.levelsJson);
    s.bind(7, r.taskId).bind(8, r.task).bind(9, r.trial).bind(10, r.question).bind(11, r.questionsInTrial);
    s.bind(12, r.stimulusKey).bind(13, std::int64_t(r.probeSeed)).bind(14, r.questionJson).bind(15, r.answerKind);
    s.bind(16, r.truthJson).bind(17, r.timeLimitSeconds).bind(18, r.trialTimeLimitSeconds).bind(19, r.stimulusPath);
    s.bind(20, r.stimulusSha256);
    s.run();
  }
  t.commit();
}

std::vector<TrialRecord> SessionStore::trials(std::int64_t participantId) {
  Statement s = db_.prepare(
      "SELECT t.id, sequence, phase, block, condition, levels_json, task_id, task, t.trial, question, questions_in_trial, "
      "stimulus_key, probe_seed, question_json, answer_kind, truth_json, time_limit, trial_time_limit, stimulus_path, "
      "stimulus_sha256, r.id IS NOT NULL FROM trials t LEFT JOIN responses r ON r.trial = t.id WHERE t.participant = ?1 "
      "ORDER BY sequence");
  s.bind(1, participantId);
  std::vector<TrialRecord> out;
  while (s.step()) {
    TrialRecord r;
    r.id = s.integer(0);
    r.sequence = int(s.integer(1));
    r.phase = s.text(2);
    r.block = int(s.integer(3));
    r.condition = s.text(4);
    r.levelsJson = s.text(5);
    r.taskId = s.text(6);
    r.task = s.text(7);
    r.trial = int(s.integer(8));
    r.question = int(s.integer(9));
    r.questionsInTrial = int(s.integer(10));
    r.stimulusKey = s.text(11);
    r.probeSeed = std::uint64_t(s.integer(12));
    r.questionJson = s.text(13);
    r.answerKind = s.text(14);
    r.truthJson = s.text(15);
    r.timeLimitSeconds = s.real(16);
    r.trialTimeLimitSeconds = s.optionalReal(17);
    r.stimulusPath = s.text(18);
    r.stimulusSha256 = s.text(19);
    r.answered = s.integer(20) != 0;
    out.push_back(std::move(r));
  }
  return out;
}

void SessionStore::recordResponse(const ResponseRecord& r) {
  Transaction t(db_);
  Statement s = db_.prepare(
      "INSERT INTO responses (trial, session, raw_answer, answered, correct, score, partial_credit, error, rt_seconds, "
      "onset_ns, response_ns, note, recorded_at) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13)");
  s.bind(1, r.trial).bind(2, r.session).bind(3, r.rawAnswer).bind(4, int(r.answered)).bind(5, int(r.correct)).bind(6, r.score);
  s.bind(7, r.partialCredit).bind(8, r.error).bind(9, r.rtSeconds).bind(10, r.onsetNs).bind(11, r.responseNs).bind(12, r.note);
  s.bind(13, utcTimestamp());
  try {
    s.run();
  } catch (const StoreError& e) {
    if (e.code() != SQLITE_CONSTRAINT_UNIQUE) throw;
    throw StoreError(db_.path() + ": trial " + std::to_string(r.trial) +
                         " already has a response: is this participant's session running at another station too?",
                     e.code());
  }
  Statement e = db_.prepare("INSERT INTO events (session, trial, t_ns, kind, detail) VALUES (?1, ?2, ?3, 'response', ?4)");
  e.bind(1, r.session).bind(2, r.trial).bind(3, r.responseNs).bind(4, r.answered ? "answered" : "missing").run();
  t.commit();
}

void SessionStore::recordEvent(std::int64_t session, std::optional<std::int64_t> trial, std::int64_t tNs, const std::string& kind,
                               const std::string& detail) {
  Statement e = db_.prepare("INSERT INTO events (session, trial, t_ns, kind, detail) VALUES (?1, ?2, ?3, ?4, ?5)");
  e.bind(1, session);
  if (trial) e.bind(2, *trial);
  else e.bindNull(2);
  e.bind(3, tNs).bind(4, kind).bind(5, detail).run();
}

void SessionStore::recordQuestionnaire(std::int64_t participantId, std::int64_t session, const std::string& questionnaire, int block,
                                       const std::vector<std::pair<std::string, int>>& itemValues) {
  Transaction t(db_);
  Statement s = db_.prepare(
      "INSERT INTO questionnaire_answers (participant, session, questionnaire, block, item, value, recorded_at) "
      "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
  for (const auto& [item, value] : itemValues) {
    s.bind(1, participantId).bind(2, session).bind(3, questionnaire).bind(4, block).bind(5, item).bind(6, value);
    s.bind(7, utcTimestamp()).run();
  }
  t.commit();
}

bool SessionStore::hasQuestionnaireAnswers(std::int64_t participantId, const std::string& questionnaire, int block) {
  Statement s = db_.prepare("SELECT 1 FROM questionnaire_answers WHERE participant = ?1 AND questionnaire = ?2 AND block = ?3 LIMIT 1");
  s.bind(1, participantId).bind(2, questionnaire).bind(3, block);
  return s.step();
}

}  // namespace tlab::study
