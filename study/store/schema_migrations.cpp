#include "study/store/schema_migrations.hpp"

#include "study/store/store.hpp"

namespace tlab::study {

namespace {

// Version 1: the tables of the first study database.
constexpr const char* kVersion1 = R"sql(
CREATE TABLE IF NOT EXISTS experiments (
  id INTEGER PRIMARY KEY, experiment_id TEXT NOT NULL, file_path TEXT NOT NULL, file_text TEXT NOT NULL,
  sha256 TEXT NOT NULL UNIQUE, tlab_version TEXT NOT NULL, created_at TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS participants (
  id INTEGER PRIMARY KEY, experiment INTEGER NOT NULL REFERENCES experiments(id), participant TEXT NOT NULL,
  slot INTEGER NOT NULL, status TEXT NOT NULL, created_at TEXT NOT NULL, finished_at TEXT,
  UNIQUE(experiment, participant));
CREATE TABLE IF NOT EXISTS assignments (
  id INTEGER PRIMARY KEY, experiment INTEGER NOT NULL REFERENCES experiments(id), slot INTEGER NOT NULL,
  participant INTEGER NOT NULL REFERENCES participants(id), design_row INTEGER NOT NULL, between_cell INTEGER NOT NULL,
  block_order TEXT NOT NULL, status TEXT NOT NULL, assigned_at TEXT NOT NULL, note TEXT);
CREATE TABLE IF NOT EXISTS sessions (
  id INTEGER PRIMARY KEY, participant INTEGER NOT NULL REFERENCES participants(id), mode TEXT NOT NULL,
  started_at TEXT NOT NULL, ended_at TEXT, end_reason TEXT);
CREATE TABLE IF NOT EXISTS trials (
  id INTEGER PRIMARY KEY, participant INTEGER NOT NULL REFERENCES participants(id), sequence INTEGER NOT NULL,
  phase TEXT NOT NULL, block INTEGER NOT NULL, condition TEXT NOT NULL, levels_json TEXT NOT NULL,
  task_id TEXT NOT NULL, task TEXT NOT NULL, trial INTEGER NOT NULL, question INTEGER NOT NULL,
  questions_in_trial INTEGER NOT NULL, stimulus_key TEXT NOT NULL, probe_seed INTEGER NOT NULL,
  question_json TEXT NOT NULL, answer_kind TEXT NOT NULL, truth_json TEXT NOT NULL, time_limit REAL NOT NULL,
  trial_time_limit REAL, stimulus_path TEXT NOT NULL, stimulus_sha256 TEXT NOT NULL,
  UNIQUE(participant, sequence));
CREATE TABLE IF NOT EXISTS responses (
  id INTEGER PRIMARY KEY, trial INTEGER NOT NULL UNIQUE REFERENCES trials(id), session INTEGER NOT NULL REFERENCES sessions(id),
  raw_answer TEXT, answered INTEGER NOT NULL, correct INTEGER NOT NULL, score REAL NOT NULL, partial_credit REAL,
  error REAL, rt_seconds REAL, onset_ns INTEGER NOT NULL, response_ns INTEGER NOT NULL, note TEXT NOT NULL,
  recorded_at TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS events (
  id INTEGER PRIMARY KEY, session INTEGER NOT NULL REFERENCES sessions(id), trial INTEGER REFERENCES trials(id),
  t_ns INTEGER NOT NULL, kind TEXT NOT NULL, detail TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS questionnaire_answers (
  id INTEGER PRIMARY KEY, participant INTEGER NOT NULL REFERENCES participants(id), session INTEGER NOT NULL REFERENCES sessions(id),
  questionnaire TEXT NOT NULL, block INTEGER NOT NULL, item TEXT NOT NULL, value INTEGER NOT NULL, recorded_at TEXT NOT NULL,
  UNIQUE(participant, questionnaire, block, item));
)sql";

// Version 2: the station (host:pid) that ran each session, indexes for per-session reads of large
// studies, and a record of the migrations themselves.
constexpr const char* kVersion2 = R"sql(
ALTER TABLE sessions ADD COLUMN station TEXT;
CREATE INDEX IF NOT EXISTS responses_by_session ON responses(session);
CREATE INDEX IF NOT EXISTS events_by_session ON events(session);
CREATE TABLE IF NOT EXISTS schema_migrations (
  version INTEGER PRIMARY KEY, description TEXT NOT NULL, applied_at TEXT NOT NULL);
)sql";

// Version 3: versions of an experiment (same id, another file text), the version each session
// ran, sessions left open by a crash marked as resumed by a later one, the process start time of
// a session's station (is it still running?), and an index for the onsets of a trial.
constexpr const char* kVersion3 = R"sql(
ALTER TABLE experiments ADD COLUMN version INTEGER NOT NULL DEFAULT 1;
UPDATE experiments SET version = (SELECT count(*) FROM experiments e2
  WHERE e2.experiment_id = experiments.experiment_id AND e2.id <= experiments.id);
ALTER TABLE sessions ADD COLUMN experiment INTEGER REFERENCES experiments(id);
UPDATE sessions SET experiment = (SELECT p.experiment FROM participants p WHERE p.id = sessions.participant);
ALTER TABLE sessions ADD COLUMN resumed_by INTEGER REFERENCES sessions(id);
ALTER TABLE sessions ADD COLUMN process_start TEXT;
CREATE INDEX IF NOT EXISTS events_by_trial ON events(trial, kind);
)sql";

// Version 4: the participant's session flow — consent decisions, participant information,
// questionnaire answers of every kind (the text as given, and its number where it has one), the
// display a session ran on, and the frame timing of every trial.
constexpr const char* kVersion4 = R"sql(
CREATE TABLE consent (
  id INTEGER PRIMARY KEY, participant INTEGER NOT NULL REFERENCES participants(id), session INTEGER REFERENCES sessions(id),
  decision TEXT NOT NULL, recorded_at TEXT NOT NULL);
CREATE TABLE participant_info (
  id INTEGER PRIMARY KEY, participant INTEGER NOT NULL REFERENCES participants(id), session INTEGER NOT NULL REFERENCES sessions(id),
  field TEXT NOT NULL, value TEXT NOT NULL, number REAL, recorded_at TEXT NOT NULL, UNIQUE(participant, field));
CREATE TABLE questionnaire_answers_v4 (
  id INTEGER PRIMARY KEY, participant INTEGER NOT NULL REFERENCES participants(id), session INTEGER NOT NULL REFERENCES sessions(id),
  questionnaire TEXT NOT NULL, block INTEGER NOT NULL, item TEXT NOT NULL, value REAL, answer TEXT NOT NULL, recorded_at TEXT NOT NULL,
  UNIQUE(participant, questionnaire, block, item));
INSERT INTO questionnaire_answers_v4 (id, participant, session, questionnaire, block, item, value, answer, recorded_at)
  SELECT id, participant, session, questionnaire, block, item, value, CAST(value AS TEXT), recorded_at FROM questionnaire_answers;
DROP TABLE questionnaire_answers;
ALTER TABLE questionnaire_answers_v4 RENAME TO questionnaire_answers;
ALTER TABLE sessions ADD COLUMN display_json TEXT;
ALTER TABLE responses ADD COLUMN onset_frame_ms REAL;
ALTER TABLE responses ADD COLUMN late_frames INTEGER;
ALTER TABLE responses ADD COLUMN onset_to_swap_ms REAL;
)sql";

}  // namespace

const std::vector<SchemaMigration>& schemaMigrations() {
  static const std::vector<SchemaMigration> migrations = {
      {1, "study tables", kVersion1},
      {2, "sessions.station, per-session indexes, schema_migrations", kVersion2},
      {3, "experiment versions, sessions.experiment/resumed_by/process_start, onset index", kVersion3},
      {4, "consent, participant_info, questionnaire answers of every kind, display and frame timing", kVersion4},
  };
  return migrations;
}

int latestSchemaVersion() { return schemaMigrations().back().version; }

int migrateSchema(Database& db, int target) {
  int ran = 0;
  for (const auto& m : schemaMigrations()) {
    if (m.version > target || db.userVersion() >= m.version) continue;
    Transaction t(db);
    if (db.userVersion() >= m.version) continue;  // another process migrated it meanwhile
    db.execute(m.sql.c_str());
    if (m.version >= 2) {
      Statement record = db.prepare("INSERT INTO schema_migrations (version, description, applied_at) VALUES (?1, ?2, ?3)");
      record.bind(1, m.version).bind(2, m.description).bind(3, utcTimestamp()).run();
    }
    db.execute(("PRAGMA user_version = " + std::to_string(m.version)).c_str());
    t.commit();
    ++ran;
  }
  return ran;
}

}  // namespace tlab::study
