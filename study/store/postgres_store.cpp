// PostgresStore: versions, enrolment, sessions, the plan, onsets, responses, events and forms, in
// the statements both stores share (study/store/store_sql.hpp); the tables export and analysis
// read: postgres_store_tables.cpp. Enrolment, session starts and declines of one experiment take
// a transaction-scoped advisory lock on its id, so concurrent stations and server threads see each
// other's slots, versions and sessions (SQLite gets the same from its one writer at a time).
// Over 300 lines: it holds the study log's writes in one place, as SqliteStore does.
#include "study/store/postgres_store.hpp"

#include "core/sha256.hpp"
#include "study/store/fault_point.hpp"
#include "study/store/postgres_connection.hpp"
#include "study/store/postgres_schema.hpp"
#include "study/store/store_records.hpp"
#include "study/store/store_sql.hpp"

namespace tlab::study {

namespace {

std::string text(const pqxx::field& f) { return std::string(f.c_str(), f.size()); }

std::string returningId(const char* insert) { return std::string(insert) + " RETURNING id"; }

// One experiment's enrolments, versions and session starts, one transaction at a time.
void lockExperiment(PgTransaction& t, const std::string& experimentId) {
  t.exec("SELECT pg_advisory_xact_lock(1952541027, hashtext(?1))", pgParams(experimentId));
}

std::vector<ExperimentVersion> versionsIn(PgTransaction& t, const std::string& experimentId) {
  std::vector<ExperimentVersion> out;
  for (const auto& r : t.exec(store_sql::kVersions, pgParams(experimentId)))
    out.push_back({r[0].as<std::int64_t>(), text(r[1]), r[2].as<int>(), text(r[3]), text(r[4]), text(r[5])});
  return out;
}

std::optional<ParticipantRecord> findParticipantIn(PgTransaction& t, const std::string& experimentId, const std::string& participant) {
  const auto r = t.exec(store_sql::kFindParticipant, pgParams(experimentId, participant));
  if (r.empty()) return std::nullopt;
  return ParticipantRecord{r[0][0].as<std::int64_t>(), r[0][1].as<std::int64_t>(), text(r[0][2]), r[0][3].as<int>(), text(r[0][4])};
}

int nextFreeSlotIn(PgTransaction& t, const std::string& experimentId) {
  int slot = 0;
  for (const auto& r : t.exec(store_sql::kTakenSlots, pgParams(experimentId))) {
    if (r[0].as<int>() != slot) break;
    ++slot;
  }
  return slot;
}

ExperimentVersion ensureVersionIn(PgTransaction& t, const std::string& location, const Experiment& e, const std::string& tlabVersion) {
  const std::string hash = core::sha256Hex(e.text);
  const auto all = versionsIn(t, e.id);
  if (auto known = versionWithText(all, e.text)) return *known;
  if (!t.exec(store_sql::kVersionOfText, pgParams(hash)).empty())  // the id is part of the text: cannot happen
    throw StoreError(location + ": holds this file's text under another experiment id");
  const int version = int(all.size()) + 1;
  const std::int64_t row =
      t.integer(returningId(store_sql::kInsertVersion), pgParams(e.id, e.path, e.text, hash, tlabVersion, utcTimestamp(), version));
  return {row, e.id, version, hash, e.path, e.text};
}

// The plan in statements of up to 500 rows (one round trip each, not one per trial).
void insertTrialsIn(PgTransaction& t, std::int64_t participantId, const std::vector<TrialRecord>& trials) {
  constexpr std::size_t kRows = 500;
  for (std::size_t first = 0; first < trials.size(); first += kRows) {
    std::string sql = std::string("INSERT INTO trials (") + store_sql::kTrialColumns + ") VALUES ";
    PgParams params;
    for (std::size_t i = first; i < std::min(trials.size(), first + kRows); ++i) {
      const auto& r = trials[i];
      sql += i == first ? "(" : ", (";
      for (int c = 1; c <= store_sql::kTrialColumnCount; ++c)
        sql += (c > 1 ? ", $" : "$") + std::to_string(params.size() + std::size_t(c));
      sql += ")";
      const PgParams row = pgParams(participantId, r.sequence, r.phase, r.block, r.condition, r.levelsJson, r.taskId, r.task, r.trial,
                                    r.question, r.questionsInTrial, r.stimulusKey, std::int64_t(r.probeSeed), r.questionJson,
                                    r.answerKind, r.truthJson, r.timeLimitSeconds, r.trialTimeLimitSeconds, r.stimulusPath,
                                    r.stimulusSha256);
      params.insert(params.end(), row.begin(), row.end());
    }
    t.exec(sql, params);
  }
}

}  // namespace

PostgresStore::PostgresStore(const std::string& url, OpenMode mode) : connection_(std::make_unique<PostgresConnection>(url, mode)) {
  preparePostgresSchema(*connection_);
}

PostgresStore::~PostgresStore() = default;

const std::string& PostgresStore::location() const { return connection_->location(); }

bool PostgresStore::exists(const std::string& sql, const PgParams& params) {
  bool found = false;
  connection_->read([&](PgTransaction& t) { found = !t.exec(sql, params).empty(); });
  return found;
}

std::vector<std::string> PostgresStore::experimentIds() {
  std::vector<std::string> ids;
  connection_->read([&](PgTransaction& t) {
    ids.clear();
    for (const auto& r : t.exec(store_sql::kExperimentIds)) ids.push_back(text(r[0]));
  });
  return ids;
}

std::vector<ExperimentVersion> PostgresStore::versions(const std::string& experimentId) {
  std::vector<ExperimentVersion> out;
  connection_->read([&](PgTransaction& t) { out = versionsIn(t, experimentId); });
  return out;
}

std::optional<ExperimentVersion> PostgresStore::findVersion(const Experiment& e) { return versionWithText(versions(e.id), e.text); }

std::optional<std::int64_t> PostgresStore::findExperiment(const std::string& experimentId) { return newestVersionRow(versions(experimentId)); }

int PostgresStore::sessionCount(std::int64_t versionRow) {
  std::int64_t count = 0;
  connection_->read([&](PgTransaction& t) { count = t.integer(store_sql::kSessionCount, pgParams(versionRow)); });
  return int(count);
}

std::optional<ParticipantRecord> PostgresStore::findParticipant(const std::string& experimentId, const std::string& participant) {
  std::optional<ParticipantRecord> out;
  connection_->read([&](PgTransaction& t) { out = findParticipantIn(t, experimentId, participant); });
  return out;
}

int PostgresStore::nextFreeSlot(const std::string& experimentId) {
  int slot = 0;
  connection_->read([&](PgTransaction& t) { slot = nextFreeSlotIn(t, experimentId); });
  return slot;
}

std::optional<ParticipantRecord> PostgresStore::enrol(const Experiment& e, const std::string& tlabVersion, const std::string& participant,
                                                      int slot, const Design& design, const std::vector<TrialRecord>& trials) {
  std::optional<ParticipantRecord> out;
  connection_->transact("the enrolment", [&](PgTransaction& t) {
    out.reset();
    lockExperiment(t, e.id);
    if (findParticipantIn(t, e.id, participant)) throw StoreError(enrolledElsewhereMessage(location(), participant));
    if (nextFreeSlotIn(t, e.id) != slot) return;  // taken meanwhile: nothing written
    const ExperimentVersion version = ensureVersionIn(t, location(), e, tlabVersion);
    const std::int64_t id =
        t.integer(returningId(store_sql::kInsertParticipant), pgParams(version.row, participant, slot, utcTimestamp()));
    const SlotDesign d = design.slot(slot);
    t.exec(store_sql::kInsertAssignment, pgParams(version.row, slot, id, d.row, d.betweenCell, blockOrderText(design, d), utcTimestamp()));
    insertTrialsIn(t, id, trials);
    out = ParticipantRecord{id, version.row, participant, slot, "active"};
  });
  return out;
}

void PostgresStore::dropParticipant(const std::string& experimentId, const std::string& participant, const std::string& reason) {
  const auto p = findParticipant(experimentId, participant);
  if (!p) throw StoreError(location() + ": no participant '" + participant + "' in this experiment");
  if (p->status == "dropped") throw StoreError("participant '" + participant + "' has already dropped out");
  connection_->transact("the dropout", [&](PgTransaction& t) {
    t.exec(store_sql::kDropParticipant, pgParams(p->id));
    t.exec(store_sql::kDropAssignment, pgParams(p->id, reason));
  });
}

void PostgresStore::finishParticipant(std::int64_t participantId) {
  connection_->transact("the participant's end", [&](PgTransaction& t) {
    t.exec(store_sql::kFinishParticipant, pgParams(participantId, utcTimestamp()));
    t.exec(store_sql::kFinishAssignment, pgParams(participantId));
  });
}

std::vector<AssignmentRecord> PostgresStore::assignments(const std::string& experimentId) {
  std::vector<AssignmentRecord> out;
  connection_->read([&](PgTransaction& t) {
    out.clear();
    for (const auto& r : t.exec(store_sql::kAssignments, pgParams(experimentId)))
      out.push_back({r[0].as<int>(), r[1].as<int>(), r[2].as<int>(), text(r[3]), text(r[4]), text(r[5])});
  });
  return out;
}

std::int64_t PostgresStore::startSession(std::int64_t participantId, const Experiment& e, const std::string& tlabVersion,
                                          const std::string& mode) {
  std::int64_t session = 0;
  connection_->transact("the new session", [&](PgTransaction& t) {
    lockExperiment(t, e.id);
    const ExperimentVersion version = ensureVersionIn(t, location(), e, tlabVersion);
    std::vector<std::int64_t> interrupted;
    for (const auto& r : t.exec(store_sql::kOpenSessions, pgParams(participantId))) {
      const std::string station = text(r[1]), state = openSessionState(station, text(r[2]));
      if (state != "dead")
        throw SessionConflict(sessionConflictMessage(location(), text(r[4]), r[0].as<std::int64_t>(), station, text(r[3]), state));
      interrupted.push_back(r[0].as<std::int64_t>());
    }
    session = t.integer(returningId(store_sql::kInsertSession),
                        pgParams(participantId, mode, utcTimestamp(), stationName(), version.row, processStartTime()));
    for (const auto id : interrupted) t.exec(store_sql::kMarkInterrupted, pgParams(id, session));
  });
  return session;
}

void PostgresStore::endSession(std::int64_t session, const std::string& reason) {
  connection_->transact("the session's end", [&](PgTransaction& t) { t.exec(store_sql::kEndSession, pgParams(session, utcTimestamp(), reason)); });
}

void PostgresStore::insertTrials(std::int64_t participantId, const std::vector<TrialRecord>& trials) {
  connection_->transact("the plan", [&](PgTransaction& t) { insertTrialsIn(t, participantId, trials); });
}

std::vector<TrialRecord> PostgresStore::trials(std::int64_t participantId) {
  std::vector<TrialRecord> out;
  connection_->read([&](PgTransaction& t) {
    out.clear();
    for (const auto& s : t.exec(store_sql::kTrials, pgParams(participantId))) {
      TrialRecord r;
      r.id = s[0].as<std::int64_t>();
      r.sequence = s[1].as<int>();
      r.phase = text(s[2]);
      r.block = s[3].as<int>();
      r.condition = text(s[4]);
      r.levelsJson = text(s[5]);
      r.taskId = text(s[6]);
      r.task = text(s[7]);
      r.trial = s[8].as<int>();
      r.question = s[9].as<int>();
      r.questionsInTrial = s[10].as<int>();
      r.stimulusKey = text(s[11]);
      r.probeSeed = std::uint64_t(s[12].as<std::int64_t>());
      r.questionJson = text(s[13]);
      r.answerKind = text(s[14]);
      r.truthJson = text(s[15]);
      r.timeLimitSeconds = s[16].as<double>();
      if (!s[17].is_null()) r.trialTimeLimitSeconds = s[17].as<double>();
      r.stimulusPath = text(s[18]);
      r.stimulusSha256 = text(s[19]);
      r.answered = s[20].as<int>() != 0;
      out.push_back(std::move(r));
    }
  });
  return out;
}

std::map<std::string, double> PostgresStore::usedSeconds(std::int64_t participantId) {
  std::map<std::string, double> out;
  connection_->read([&](PgTransaction& t) {
    out.clear();
    for (const auto& r : t.exec(store_sql::kUsedSeconds, pgParams(participantId)))
      out[text(r[0]) + "/" + text(r[1]) + "/" + text(r[2]) + "/" + text(r[3])] += r[4].as<double>();
  });
  return out;
}

int PostgresStore::recordOnset(std::int64_t session, std::int64_t trial, std::int64_t tNs, const std::string& detail) {
  int shown = 0;
  connection_->transact("the stimulus onset", [&](PgTransaction& t) {
    t.exec("SELECT id FROM trials WHERE id = ?1 FOR UPDATE", pgParams(trial));  // one onset of a trial at a time: counts stay exact
    shown = int(t.integer(store_sql::kOnsetCount, pgParams(trial))) + 1;
    t.exec(store_sql::kInsertEvent, pgParams(session, trial, tNs, std::string("onset"), onsetDetail(detail, shown)));
  });
  return shown;
}

void PostgresStore::recordResponse(const ResponseRecord& r) {
  connection_->transact("the answer", [&](PgTransaction& t) {
    // The unique trial column decides between two stations answering one trial; the loser writes nothing.
    const auto inserted = t.exec(std::string(store_sql::kInsertResponse) + " ON CONFLICT (trial) DO NOTHING RETURNING id",
                                 pgParams(r.trial, r.session, r.rawAnswer, int(r.answered), int(r.correct), r.score, r.partialCredit,
                                          r.error, r.rtSeconds, r.onsetNs, r.responseNs, r.note, utcTimestamp(), r.onsetFrameMs,
                                          r.lateFrames, r.onsetToSwapMs));
    if (inserted.empty()) throw StoreError(duplicateResponseMessage(location(), r.trial));
    t.exec(store_sql::kInsertResponseEvent, pgParams(r.session, r.trial, r.responseNs, std::string(r.answered ? "answered" : "missing")));
    faultPoint("commit", ++responses_);
  });
}

void PostgresStore::recordEvent(std::int64_t session, std::optional<std::int64_t> trial, std::int64_t tNs, const std::string& kind,
                                const std::string& detail) {
  connection_->transact("the " + kind + " event", [&](PgTransaction& t) {
    t.exec(store_sql::kInsertEvent, pgParams(session, trial, tNs, kind, detail));
  });
}

void PostgresStore::recordEvents(std::int64_t session, std::optional<std::int64_t> trial, const std::vector<EventRecord>& events) {
  if (events.empty()) return;
  connection_->transact("the session's events", [&](PgTransaction& t) {
    for (const auto& e : events) t.exec(store_sql::kInsertEvent, pgParams(session, trial, e.tNs, e.kind, e.detail));
  });
}

void PostgresStore::recordQuestionnaire(std::int64_t participantId, std::int64_t session, const std::string& questionnaire, int block,
                                        const std::vector<FormAnswer>& answers) {
  connection_->transact("the questionnaire answers", [&](PgTransaction& t) {
    for (const auto& a : answers)
      t.exec(store_sql::kInsertQuestionnaireAnswer,
             pgParams(participantId, session, questionnaire, block, a.field, a.number, a.value, utcTimestamp()));
  });
}

bool PostgresStore::hasQuestionnaireAnswers(std::int64_t participantId, const std::string& questionnaire, int block) {
  return exists(store_sql::kHasQuestionnaireAnswers, pgParams(participantId, questionnaire, block));
}

void PostgresStore::recordDecline(const Experiment& e, const std::string& tlabVersion, const std::string& participant) {
  connection_->transact("the declined consent", [&](PgTransaction& t) {
    lockExperiment(t, e.id);
    if (findParticipantIn(t, e.id, participant)) throw StoreError(location() + ": participant '" + participant + "' is already known");
    const ExperimentVersion version = ensureVersionIn(t, location(), e, tlabVersion);
    const std::int64_t id = t.integer(returningId(store_sql::kInsertDecliner), pgParams(version.row, participant, utcTimestamp()));
    t.exec(store_sql::kInsertDecline, pgParams(id, utcTimestamp()));
  });
}

void PostgresStore::recordConsent(std::int64_t participantId, std::int64_t session, bool accepted) {
  connection_->transact("the consent decision", [&](PgTransaction& t) {
    t.exec(store_sql::kInsertConsent, pgParams(participantId, session, std::string(accepted ? "accepted" : "declined"), utcTimestamp()));
  });
}

bool PostgresStore::hasConsent(std::int64_t participantId) { return exists(store_sql::kHasConsent, pgParams(participantId)); }

void PostgresStore::recordInfo(std::int64_t participantId, std::int64_t session, const std::vector<FormAnswer>& answers) {
  connection_->transact("the participant information", [&](PgTransaction& t) {
    for (const auto& a : answers) t.exec(store_sql::kInsertInfo, pgParams(participantId, session, a.field, a.value, a.number, utcTimestamp()));
  });
}

std::optional<std::string> PostgresStore::lastEventDetail(std::int64_t participantId, const std::string& kind) {
  std::optional<std::string> detail;
  connection_->read([&](PgTransaction& t) {
    const auto r = t.exec(store_sql::kLastEventDetail, pgParams(participantId, kind));
    if (!r.empty()) detail = text(r[0][0]);
  });
  return detail;
}

bool PostgresStore::hasInfo(std::int64_t participantId) { return exists(store_sql::kHasInfo, pgParams(participantId)); }

void PostgresStore::recordDisplay(std::int64_t session, const std::string& displayJson) {
  connection_->transact("the display", [&](PgTransaction& t) { t.exec(store_sql::kRecordDisplay, pgParams(session, displayJson)); });
}

}  // namespace tlab::study
