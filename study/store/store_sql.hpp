#pragma once
// The statements both stores run (SqliteStore as written; PostgresStore with ?N read as $N and
// RETURNING id after an insert whose row it needs). Only study/store/ includes this header.
namespace tlab::study::store_sql {

// Experiment versions.
inline constexpr const char* kVersions =
    "SELECT id, experiment_id, version, sha256, file_path, file_text FROM experiments WHERE experiment_id = ?1 ORDER BY version, id";
inline constexpr const char* kExperimentIds = "SELECT experiment_id FROM experiments GROUP BY experiment_id ORDER BY min(id)";
inline constexpr const char* kSessionCount = "SELECT count(*) FROM sessions WHERE experiment = ?1";
inline constexpr const char* kVersionOfText = "SELECT id FROM experiments WHERE sha256 = ?1";
inline constexpr const char* kInsertVersion =
    "INSERT INTO experiments (experiment_id, file_path, file_text, sha256, tlab_version, created_at, version) "
    "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)";

// Participants, slots and assignments.
inline constexpr const char* kFindParticipant =
    "SELECT p.id, p.experiment, p.participant, p.slot, p.status FROM participants p JOIN experiments x ON x.id = p.experiment "
    "WHERE x.experiment_id = ?1 AND p.participant = ?2";
inline constexpr const char* kTakenSlots =
    "SELECT DISTINCT a.slot FROM assignments a JOIN experiments x ON x.id = a.experiment "
    "WHERE x.experiment_id = ?1 AND a.status != 'dropped' ORDER BY a.slot";
inline constexpr const char* kInsertParticipant =
    "INSERT INTO participants (experiment, participant, slot, status, created_at) VALUES (?1, ?2, ?3, 'active', ?4)";
inline constexpr const char* kInsertAssignment =
    "INSERT INTO assignments (experiment, slot, participant, design_row, between_cell, block_order, status, assigned_at) "
    "VALUES (?1, ?2, ?3, ?4, ?5, ?6, 'active', ?7)";
inline constexpr const char* kDropParticipant = "UPDATE participants SET status = 'dropped' WHERE id = ?1";
inline constexpr const char* kDropAssignment = "UPDATE assignments SET status = 'dropped', note = ?2 WHERE participant = ?1";
inline constexpr const char* kFinishParticipant = "UPDATE participants SET status = 'finished', finished_at = ?2 WHERE id = ?1";
inline constexpr const char* kFinishAssignment = "UPDATE assignments SET status = 'finished' WHERE participant = ?1 AND status = 'active'";
inline constexpr const char* kAssignments =
    "SELECT a.slot, a.design_row, a.between_cell, p.participant, a.status, a.block_order FROM assignments a "
    "JOIN participants p ON p.id = a.participant JOIN experiments x ON x.id = a.experiment WHERE x.experiment_id = ?1 "
    "ORDER BY a.slot, a.id";
inline constexpr const char* kInsertDecliner =
    "INSERT INTO participants (experiment, participant, slot, status, created_at) VALUES (?1, ?2, -1, 'declined', ?3)";
inline constexpr const char* kInsertDecline =
    "INSERT INTO consent (participant, session, decision, recorded_at) VALUES (?1, NULL, 'declined', ?2)";

// Sessions.
inline constexpr const char* kOpenSessions =
    "SELECT s.id, coalesce(s.station, ''), coalesce(s.process_start, ''), s.started_at, p.participant FROM sessions s "
    "JOIN participants p ON p.id = s.participant WHERE s.participant = ?1 AND s.ended_at IS NULL AND s.resumed_by IS NULL";
inline constexpr const char* kInsertSession =
    "INSERT INTO sessions (participant, mode, started_at, station, experiment, process_start) VALUES (?1, ?2, ?3, ?4, ?5, ?6)";
inline constexpr const char* kMarkInterrupted = "UPDATE sessions SET end_reason = 'interrupted', resumed_by = ?2 WHERE id = ?1";
inline constexpr const char* kEndSession = "UPDATE sessions SET ended_at = ?2, end_reason = ?3 WHERE id = ?1";
inline constexpr const char* kRecordDisplay = "UPDATE sessions SET display_json = ?2 WHERE id = ?1";

// The plan, onsets, responses and events.
inline constexpr const char* kTrialColumns =
    "participant, sequence, phase, block, condition, levels_json, task_id, task, trial, question, questions_in_trial, stimulus_key, "
    "probe_seed, question_json, answer_kind, truth_json, time_limit, trial_time_limit, stimulus_path, stimulus_sha256";
inline constexpr int kTrialColumnCount = 20;
inline constexpr const char* kTrials =
    "SELECT t.id, sequence, phase, block, condition, levels_json, task_id, task, t.trial, question, questions_in_trial, "
    "stimulus_key, probe_seed, question_json, answer_kind, truth_json, time_limit, trial_time_limit, stimulus_path, "
    "stimulus_sha256, CASE WHEN r.id IS NULL THEN 0 ELSE 1 END FROM trials t LEFT JOIN responses r ON r.trial = t.id "
    "WHERE t.participant = ?1 ORDER BY sequence";
inline constexpr const char* kUsedSeconds =
    "SELECT t.phase, t.block, t.task_id, t.trial, coalesce(r.rt_seconds, t.time_limit) FROM responses r "
    "JOIN trials t ON t.id = r.trial WHERE t.participant = ?1";
inline constexpr const char* kOnsetCount = "SELECT count(*) FROM events WHERE trial = ?1 AND kind = 'onset'";
inline constexpr const char* kInsertResponse =
    "INSERT INTO responses (trial, session, raw_answer, answered, correct, score, partial_credit, error, rt_seconds, "
    "onset_ns, response_ns, note, recorded_at, onset_frame_ms, late_frames, onset_to_swap_ms) "
    "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16)";
inline constexpr const char* kInsertResponseEvent =
    "INSERT INTO events (session, trial, t_ns, kind, detail) VALUES (?1, ?2, ?3, 'response', ?4)";
inline constexpr const char* kInsertEvent = "INSERT INTO events (session, trial, t_ns, kind, detail) VALUES (?1, ?2, ?3, ?4, ?5)";

// Forms: questionnaires, consent, participant information.
inline constexpr const char* kInsertQuestionnaireAnswer =
    "INSERT INTO questionnaire_answers (participant, session, questionnaire, block, item, value, answer, recorded_at) "
    "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)";
inline constexpr const char* kHasQuestionnaireAnswers =
    "SELECT 1 FROM questionnaire_answers WHERE participant = ?1 AND questionnaire = ?2 AND block = ?3 LIMIT 1";
inline constexpr const char* kInsertConsent = "INSERT INTO consent (participant, session, decision, recorded_at) VALUES (?1, ?2, ?3, ?4)";
inline constexpr const char* kLastEventDetail =
    "SELECT e.detail FROM events e JOIN sessions s ON s.id = e.session WHERE s.participant = ?1 AND e.kind = ?2 ORDER BY e.id DESC LIMIT 1";
inline constexpr const char* kHasConsent = "SELECT 1 FROM consent WHERE participant = ?1 AND decision = 'accepted' LIMIT 1";
inline constexpr const char* kInsertInfo =
    "INSERT INTO participant_info (participant, session, field, value, number, recorded_at) VALUES (?1, ?2, ?3, ?4, ?5, ?6)";
inline constexpr const char* kHasInfo = "SELECT 1 FROM participant_info WHERE participant = ?1 LIMIT 1";

}  // namespace tlab::study::store_sql
