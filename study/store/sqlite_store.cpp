// SqliteStore: opening and checking the file, versions, enrolment, sessions, the plan, responses,
// events and questionnaires (the tables export and analysis read: sqlite_store_tables.cpp). Over
// 300 lines: it holds the SQL of the study log's writes in one place, next to one schema.
#include "study/store/sqlite_store.hpp"

#include <chrono>
#include <csignal>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <sqlite3.h>
#include <unistd.h>

#include "core/sha256.hpp"
#include "study/store/fault_point.hpp"
#include "study/store/schema_migrations.hpp"
#include "study/store/store_records.hpp"
#include "study/store/store_sql.hpp"

namespace tlab::study {

namespace {

std::string hostName() {
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0) return "unknown";
  return host;
}

// Field 22 of /proc/PID/stat (start time in clock ticks since boot); "" when unreadable.
std::string startTimeOf(const std::string& pid) {
  std::ifstream in("/proc/" + pid + "/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto close = text.rfind(')');  // the command name may hold spaces and parentheses
  if (close == std::string::npos) return "";
  std::istringstream fields(text.substr(close + 2));
  std::string field;
  for (int i = 3; i <= 22 && fields >> field; ++i)
    if (i == 22) return field;
  return "";
}

// Copies a database into memory (sqlite3_backup), so a reader can migrate an older schema there.
std::unique_ptr<Database> memoryCopy(Database& from) {
  auto copy = std::make_unique<Database>(":memory:", OpenMode::Create);
  sqlite3_backup* backup = sqlite3_backup_init(copy->handle(), "main", from.handle(), "main");
  if (!backup) throw StoreError(from.path() + ": cannot read it into memory: " + copy->explain());
  sqlite3_backup_step(backup, -1);
  if (sqlite3_backup_finish(backup) != SQLITE_OK) throw StoreError(from.path() + ": cannot read it into memory: " + copy->explain());
  return copy;
}

// PRAGMA journal_mode=WAL on a new file needs an exclusive lock while this connection already
// reads the file, and SQLite then answers BUSY at once, without its busy handler, whenever
// another process is reading it at that moment (two stations opening a new database together).
// So it is retried here, within the same deadline as every other wait.
void switchToWal(Database& db) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(kBusyTimeoutMs);
  for (int attempt = 0;; ++attempt) {
    try {
      Statement mode = db.prepare("PRAGMA journal_mode=WAL");
      if (mode.step() && mode.text(0) == "wal") return;
    } catch (const StoreError& e) {
      if ((e.code() & 0xff) != SQLITE_BUSY && (e.code() & 0xff) != SQLITE_LOCKED) throw;
    }
    if (std::chrono::steady_clock::now() > deadline)
      throw StoreError(db.path() + ": cannot switch the database to write-ahead logging: another process kept it locked for " +
                           std::to_string(kBusyTimeoutMs / 1000) + " s; let it finish, then try again",
                       SQLITE_BUSY);
    std::this_thread::sleep_for(std::chrono::milliseconds(std::min(50, 1 << std::min(attempt, 6))));
  }
}

}  // namespace

std::string stationName() { return hostName() + ":" + std::to_string(getpid()); }

std::string processStartTime() { return startTimeOf("self"); }

std::string stationState(const std::string& station, const std::string& processStart) {
  const auto colon = station.rfind(':');
  if (colon == std::string::npos || station.substr(0, colon) != hostName()) return "unknown";
  const std::string pid = station.substr(colon + 1);
  if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) return "unknown";
  const std::string started = startTimeOf(pid);
  if (started.empty()) return "dead";
  // A reused pid belongs to another process: compare start times where the session stored one.
  return processStart.empty() || processStart == started ? "alive" : "dead";
}

std::string openSessionState(const std::string& station, const std::string& processStart) {
  if (station == stationName() && processStart == processStartTime()) return "dead";
  return stationState(station, processStart);
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

SqliteStore::SqliteStore(const std::string& path, OpenMode mode) : path_(path), unwindingAtOpen_(std::uncaught_exceptions()) {
  std::error_code ec;  // an existing file (or folder) is checked before SQLite touches it; a new or empty one is created
  const bool existing = std::filesystem::is_directory(path, ec) || (std::filesystem::exists(path, ec) && std::filesystem::file_size(path, ec) > 0);
  created_ = mode != OpenMode::Read && !std::filesystem::exists(path, ec);
  if (mode == OpenMode::Write || (mode == OpenMode::Create && existing)) requireSqliteFile(path);
  db_ = std::make_unique<Database>(path, mode);
  // Everything before the first write only reads: a foreign, damaged or newer file stays untouched.
  int version = 0;
  try {
    version = requireStudyDatabase();
  } catch (const StoreError& e) {
    // A log with changes not yet in the file, in a folder we may not write: SQLite cannot replay it.
    if (mode == OpenMode::Read && (e.code() & 0xff) == SQLITE_CANTOPEN && std::filesystem::exists(path + "-wal"))
      throw StoreError(path + ": its write-ahead log (" + path + "-wal) holds changes that must be replayed, and the folder is "
                       "read-only: copy " + path + " and " + path + "-wal together to a writable folder and read the copy", e.code());
    throw;
  }
  checkIntegrity();
  if (mode == OpenMode::Read) {
    if (version < kSchemaVersion) {
      db_ = memoryCopy(*db_);
      migrateSchema(*db_);
    }
    return;
  }
  switchToWal(*db_);
  db_->execute("PRAGMA synchronous=FULL");
  db_->execute("PRAGMA foreign_keys=ON");
  migrateSchema(*db_);
}

SqliteStore::~SqliteStore() {
  if (!created_ || std::uncaught_exceptions() <= unwindingAtOpen_ || !db_) return;
  try {
    if (!experimentIds().empty()) return;
    db_.reset();
    for (const char* suffix : {"", "-wal", "-shm", "-journal"}) {
      std::error_code ec;
      std::filesystem::remove(path_ + suffix, ec);
    }
  } catch (...) {
    // a store that cannot be read now keeps its file
  }
}

int SqliteStore::requireStudyDatabase() {
  // One statement, one snapshot: another station may be creating the schema right now (its tables
  // and its user_version commit together).
  Statement s = db_->prepare("SELECT (SELECT user_version FROM pragma_user_version), group_concat(name, ', '), "
                             "coalesce(sum(name IN ('experiments', 'trials', 'responses')), 0) FROM sqlite_master WHERE type = 'table'");
  s.step();
  const int version = int(s.integer(0));
  const std::string names = s.isNull(1) ? "" : s.text(1);
  if (version > kSchemaVersion)
    throw StoreError(path_ + ": written by a newer tlab (schema version " + std::to_string(version) + "; this tlab reads up to " +
                     std::to_string(kSchemaVersion) + "): open it with that tlab or a newer one; nothing was changed");
  if (version == 0 && !names.empty())
    throw StoreError(path_ + ": not a tlab study database (it has other tables: " + names + "); nothing was changed");
  if (version > 0 && s.integer(2) != 3)
    throw StoreError(path_ + ": not a tlab study database (its tables are " + (names.empty() ? std::string("none") : names) +
                     "); nothing was changed");
  if (db_->readOnly() && version == 0) throw StoreError(path_ + ": an empty database: no experiment has been run into it yet");
  return version;
}

void SqliteStore::checkIntegrity() {
  Statement check = db_->prepare("PRAGMA quick_check(1)");
  if (check.step() && check.text(0) != "ok")
    throw StoreError(path_ + ": the database file is damaged (" + check.text(0) +
                         "); tlab does not write to it: restore it from a backup (or salvage with 'sqlite3 FILE .recover'), "
                         "then continue with --resume",
                     SQLITE_CORRUPT);
}

std::vector<ExperimentVersion> SqliteStore::versions(const std::string& experimentId) {
  Statement s = db_->prepare(store_sql::kVersions);
  s.bind(1, experimentId);
  std::vector<ExperimentVersion> out;
  while (s.step()) out.push_back({s.integer(0), s.text(1), int(s.integer(2)), s.text(3), s.text(4), s.text(5)});
  return out;
}

std::optional<ExperimentVersion> SqliteStore::findVersion(const Experiment& e) { return versionWithText(versions(e.id), e.text); }

std::vector<std::string> SqliteStore::experimentIds() {
  Statement s = db_->prepare(store_sql::kExperimentIds);
  std::vector<std::string> ids;
  while (s.step()) ids.push_back(s.text(0));
  return ids;
}

int SqliteStore::sessionCount(std::int64_t versionRow) {
  Statement count = db_->prepare(store_sql::kSessionCount);
  count.bind(1, versionRow);
  count.step();
  return int(count.integer(0));
}

std::optional<std::int64_t> SqliteStore::findExperiment(const std::string& experimentId) { return newestVersionRow(versions(experimentId)); }

ExperimentVersion SqliteStore::ensureVersion(const Experiment& e, const std::string& tlabVersion) {
  if (auto known = findVersion(e)) return *known;  // the text's own version
  const std::string hash = core::sha256Hex(e.text);
  Statement other = db_->prepare(store_sql::kVersionOfText);
  other.bind(1, hash);
  if (other.step())  // the same text under another id cannot happen: the id is part of the text
    throw StoreError(path_ + ": holds this file's text under another experiment id");
  const int version = int(versions(e.id).size()) + 1;
  Statement insert = db_->prepare(store_sql::kInsertVersion);
  insert.bind(1, e.id).bind(2, e.path).bind(3, e.text).bind(4, hash).bind(5, tlabVersion).bind(6, utcTimestamp()).bind(7, version);
  insert.run();
  return {db_->lastInsertId(), e.id, version, hash, e.path, e.text};
}

std::optional<ParticipantRecord> SqliteStore::findParticipant(const std::string& experimentId, const std::string& participant) {
  Statement s = db_->prepare(store_sql::kFindParticipant);
  s.bind(1, experimentId).bind(2, participant);
  if (!s.step()) return std::nullopt;
  return ParticipantRecord{s.integer(0), s.integer(1), s.text(2), int(s.integer(3)), s.text(4)};
}

int SqliteStore::nextFreeSlot(const std::string& experimentId) {
  Statement taken = db_->prepare(store_sql::kTakenSlots);
  taken.bind(1, experimentId);
  int slot = 0;
  while (taken.step() && taken.integer(0) == slot) ++slot;
  return slot;
}

std::optional<ParticipantRecord> SqliteStore::enrol(const Experiment& e, const std::string& tlabVersion, const std::string& participant,
                                                     int slot, const Design& design, const std::vector<TrialRecord>& trials) {
  Transaction t(*db_);
  if (findParticipant(e.id, participant))
    throw StoreError(enrolledElsewhereMessage(path_, participant));
  if (nextFreeSlot(e.id) != slot) return std::nullopt;
  const ExperimentVersion version = ensureVersion(e, tlabVersion);
  Statement insert = db_->prepare(store_sql::kInsertParticipant);
  insert.bind(1, version.row).bind(2, participant).bind(3, slot).bind(4, utcTimestamp());
  insert.run();
  const std::int64_t id = db_->lastInsertId();
  const SlotDesign d = design.slot(slot);
  Statement assign = db_->prepare(store_sql::kInsertAssignment);
  assign.bind(1, version.row).bind(2, slot).bind(3, id).bind(4, d.row).bind(5, d.betweenCell).bind(6, blockOrderText(design, d));
  assign.bind(7, utcTimestamp());
  assign.run();
  insertTrials(id, trials);
  t.commit();
  return ParticipantRecord{id, version.row, participant, slot, "active"};
}

void SqliteStore::dropParticipant(const std::string& experimentId, const std::string& participant, const std::string& reason) {
  const auto p = findParticipant(experimentId, participant);
  if (!p) throw StoreError(path_ + ": no participant '" + participant + "' in this experiment");
  if (p->status == "dropped") throw StoreError("participant '" + participant + "' has already dropped out");
  Transaction t(*db_);
  Statement a = db_->prepare(store_sql::kDropParticipant);
  a.bind(1, p->id).run();
  Statement b = db_->prepare(store_sql::kDropAssignment);
  b.bind(1, p->id).bind(2, reason).run();
  t.commit();
}

void SqliteStore::finishParticipant(std::int64_t participantId) {
  Transaction t(*db_);
  Statement a = db_->prepare(store_sql::kFinishParticipant);
  a.bind(1, participantId).bind(2, utcTimestamp()).run();
  Statement b = db_->prepare(store_sql::kFinishAssignment);
  b.bind(1, participantId).run();
  t.commit();
}

std::vector<AssignmentRecord> SqliteStore::assignments(const std::string& experimentId) {
  Statement s = db_->prepare(store_sql::kAssignments);
  s.bind(1, experimentId);
  std::vector<AssignmentRecord> out;
  while (s.step())
    out.push_back({int(s.integer(0)), int(s.integer(1)), int(s.integer(2)), s.text(3), s.text(4), s.text(5)});
  return out;
}

std::int64_t SqliteStore::startSession(std::int64_t participantId, const Experiment& e, const std::string& tlabVersion,
                                        const std::string& mode) {
  Transaction t(*db_);
  const ExperimentVersion version = ensureVersion(e, tlabVersion);
  Statement open = db_->prepare(store_sql::kOpenSessions);
  open.bind(1, participantId);
  std::vector<std::int64_t> interrupted;
  while (open.step()) {
    const std::string station = open.text(1), state = openSessionState(station, open.text(2));
    if (state == "dead") {
      interrupted.push_back(open.integer(0));
      continue;
    }
    throw SessionConflict(sessionConflictMessage(path_, open.text(4), open.integer(0), station, open.text(3), state));
  }
  Statement s = db_->prepare(store_sql::kInsertSession);
  s.bind(1, participantId).bind(2, mode).bind(3, utcTimestamp()).bind(4, stationName()).bind(5, version.row);
  s.bind(6, processStartTime()).run();
  const std::int64_t session = db_->lastInsertId();
  Statement mark = db_->prepare(store_sql::kMarkInterrupted);
  for (const auto id : interrupted) mark.bind(1, id).bind(2, session).run();
  t.commit();
  return session;
}

void SqliteStore::endSession(std::int64_t session, const std::string& reason) {
  Statement s = db_->prepare(store_sql::kEndSession);
  s.bind(1, session).bind(2, utcTimestamp()).bind(3, reason).run();
}

void SqliteStore::insertTrials(std::int64_t participantId, const std::vector<TrialRecord>& trials) {
  Transaction t(*db_);  // inside enrol's transaction: a savepoint
  std::string sql = std::string("INSERT INTO trials (") + store_sql::kTrialColumns + ") VALUES (";
  for (int c = 1; c <= store_sql::kTrialColumnCount; ++c) sql += (c > 1 ? ", ?" : "?") + std::to_string(c);
  Statement s = db_->prepare(sql + ")");
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

std::vector<TrialRecord> SqliteStore::trials(std::int64_t participantId) {
  Statement s = db_->prepare(store_sql::kTrials);
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

std::map<std::string, double> SqliteStore::usedSeconds(std::int64_t participantId) {
  Statement used = db_->prepare(store_sql::kUsedSeconds);
  used.bind(1, participantId);
  std::map<std::string, double> out;
  while (used.step())
    out[used.text(0) + "/" + std::to_string(used.integer(1)) + "/" + used.text(2) + "/" + std::to_string(used.integer(3))] += used.real(4);
  return out;
}

int SqliteStore::recordOnset(std::int64_t session, std::int64_t trial, std::int64_t tNs, const std::string& detail) {
  Transaction t(*db_);
  Statement count = db_->prepare(store_sql::kOnsetCount);
  count.bind(1, trial);
  count.step();
  const int shown = int(count.integer(0)) + 1;
  recordEvent(session, trial, tNs, "onset", onsetDetail(detail, shown));
  t.commit();
  return shown;
}

void SqliteStore::recordResponse(const ResponseRecord& r) {
  Transaction t(*db_);
  Statement s = db_->prepare(store_sql::kInsertResponse);
  s.bind(1, r.trial).bind(2, r.session).bind(3, r.rawAnswer).bind(4, int(r.answered)).bind(5, int(r.correct)).bind(6, r.score);
  s.bind(7, r.partialCredit).bind(8, r.error).bind(9, r.rtSeconds).bind(10, r.onsetNs).bind(11, r.responseNs).bind(12, r.note);
  s.bind(13, utcTimestamp()).bind(14, r.onsetFrameMs).bind(16, r.onsetToSwapMs);
  if (r.lateFrames) s.bind(15, *r.lateFrames);
  else s.bindNull(15);
  try {
    s.run();
  } catch (const StoreError& e) {
    if (e.code() != SQLITE_CONSTRAINT_UNIQUE) throw;
    throw StoreError(duplicateResponseMessage(path_, r.trial), e.code());
  }
  Statement e = db_->prepare(store_sql::kInsertResponseEvent);
  e.bind(1, r.session).bind(2, r.trial).bind(3, r.responseNs).bind(4, r.answered ? "answered" : "missing").run();
  faultPoint("commit", ++responses_);
  t.commit();
}

void SqliteStore::recordEvent(std::int64_t session, std::optional<std::int64_t> trial, std::int64_t tNs, const std::string& kind,
                               const std::string& detail) {
  Statement e = db_->prepare(store_sql::kInsertEvent);
  e.bind(1, session);
  if (trial) e.bind(2, *trial);
  else e.bindNull(2);
  e.bind(3, tNs).bind(4, kind).bind(5, detail).run();
}

void SqliteStore::recordEvents(std::int64_t session, std::optional<std::int64_t> trial, const std::vector<EventRecord>& events) {
  if (events.empty()) return;
  Transaction t(*db_);
  for (const auto& e : events) recordEvent(session, trial, e.tNs, e.kind, e.detail);
  t.commit();
}

void SqliteStore::recordQuestionnaire(std::int64_t participantId, std::int64_t session, const std::string& questionnaire, int block,
                                      const std::vector<FormAnswer>& answers) {
  Transaction t(*db_);
  Statement s = db_->prepare(store_sql::kInsertQuestionnaireAnswer);
  for (const auto& a : answers) {
    s.bind(1, participantId).bind(2, session).bind(3, questionnaire).bind(4, block).bind(5, a.field).bind(6, a.number).bind(7, a.value);
    s.bind(8, utcTimestamp()).run();
  }
  t.commit();
}

void SqliteStore::recordDecline(const Experiment& e, const std::string& tlabVersion, const std::string& participant) {
  Transaction t(*db_);
  if (findParticipant(e.id, participant)) throw StoreError(path_ + ": participant '" + participant + "' is already known");
  const ExperimentVersion version = ensureVersion(e, tlabVersion);
  Statement insert = db_->prepare(store_sql::kInsertDecliner);
  insert.bind(1, version.row).bind(2, participant).bind(3, utcTimestamp()).run();
  Statement consent = db_->prepare(store_sql::kInsertDecline);
  consent.bind(1, db_->lastInsertId()).bind(2, utcTimestamp()).run();
  t.commit();
}

void SqliteStore::recordConsent(std::int64_t participantId, std::int64_t session, bool accepted) {
  Statement s = db_->prepare(store_sql::kInsertConsent);
  s.bind(1, participantId).bind(2, session).bind(3, accepted ? "accepted" : "declined").bind(4, utcTimestamp()).run();
}

bool SqliteStore::hasConsent(std::int64_t participantId) {
  Statement s = db_->prepare(store_sql::kHasConsent);
  s.bind(1, participantId);
  return s.step();
}

void SqliteStore::recordInfo(std::int64_t participantId, std::int64_t session, const std::vector<FormAnswer>& answers) {
  Transaction t(*db_);
  Statement s = db_->prepare(store_sql::kInsertInfo);
  for (const auto& a : answers) s.bind(1, participantId).bind(2, session).bind(3, a.field).bind(4, a.value).bind(5, a.number).bind(6, utcTimestamp()).run();
  t.commit();
}

std::optional<std::string> SqliteStore::lastEventDetail(std::int64_t participantId, const std::string& kind) {
  Statement s = db_->prepare(store_sql::kLastEventDetail);
  s.bind(1, participantId).bind(2, kind);
  if (!s.step()) return std::nullopt;
  return s.text(0);
}

bool SqliteStore::hasInfo(std::int64_t participantId) {
  Statement s = db_->prepare(store_sql::kHasInfo);
  s.bind(1, participantId);
  return s.step();
}

void SqliteStore::recordDisplay(std::int64_t session, const std::string& displayJson) {
  Statement s = db_->prepare(store_sql::kRecordDisplay);
  s.bind(1, session).bind(2, displayJson).run();
}

bool SqliteStore::hasQuestionnaireAnswers(std::int64_t participantId, const std::string& questionnaire, int block) {
  Statement s = db_->prepare(store_sql::kHasQuestionnaireAnswers);
  s.bind(1, participantId).bind(2, questionnaire).bind(3, block);
  return s.step();
}

}  // namespace tlab::study
