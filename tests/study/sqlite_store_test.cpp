// The SQLite store: schema version and WAL, slots re-assigned after a dropout, one response per
// trial, and hostile participant ids and answers (quotes, SQL, 1 MB, invalid UTF-8) stored and
// exported byte for byte.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <filesystem>
#include <thread>

#include "study/store/csv_export.hpp"
#include "study/design/experiment_file.hpp"
#include "study/store/sqlite_store.hpp"
#include "study/store/study_table.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::study;
using tlab::testing::freshDir;
using tlab::testing::parseCsv;
using tlab::testing::readText;

namespace {

TrialRecord fakeTrial(int sequence) {
  TrialRecord t;
  t.sequence = sequence;
  t.phase = "test";
  t.block = 1;
  t.condition = "method=alpha, scene=cylinders";
  t.levelsJson = R"({"method":"alpha","scene":"cylinders"})";
  t.taskId = "layer";
  t.task = "layer-index";
  t.stimulusKey = "k";
  t.questionJson = "{}";
  t.answerKind = "layer-number";
  t.truthJson = "2";
  t.timeLimitSeconds = 30;
  t.stimulusPath = "s.png";
  t.stimulusSha256 = std::string(64, 'a');
  return t;
}

std::vector<std::string> hostileTexts() {
  std::string invalidUtf8 = "bad \xC3\x28 \xFF\xFE \xE2\x82 end";
  std::string big(1 << 20, 'x');
  for (std::size_t i = 0; i < big.size(); i += 997) big[i] = "\",'\n;\r"[i % 6];
  return {"'; DROP TABLE responses; --", "Robert\"); DROP TABLE participants;--", "comma, \"quote\" and\nnewline", invalidUtf8,
          big, " leading and trailing ", "", "NULL"};
}

// A new store with one enrolled participant of tiny.toml in a started session.
struct OneParticipant {
  explicit OneParticipant(const std::string& name)
      : dir(freshDir(name)), e(readExperimentFile(tlab::testing::studyData("tiny.toml"))), path((dir / "s.db").string()), store(path),
        db(path, false), p(*store.enrol(e, "test", "p", 0, makeDesign(e), {fakeTrial(1)})),
        session(store.startSession(p.id, e, "test", "simulated")) {}
  std::filesystem::path dir;
  Experiment e;
  std::string path;
  SqliteStore store;
  Database db;
  ParticipantRecord p;
  std::int64_t session;
};

}  // namespace

TEST(SqliteStore, SchemaVersionAndWal) {
  const auto dir = freshDir("store_schema");
  const std::string path = (dir / "s.db").string();
  {
    SqliteStore store(path);
    Database db(path, false);
    EXPECT_EQ(db.userVersion(), SqliteStore::kSchemaVersion);
    Statement mode = db.prepare("PRAGMA journal_mode");
    ASSERT_TRUE(mode.step());
    EXPECT_EQ(mode.text(0), "wal");
  }
  SqliteStore again(path);  // reopening keeps the schema
  EXPECT_EQ(Database(path, false).userVersion(), SqliteStore::kSchemaVersion);
  {
    Database other((dir / "other.db").string(), true);
    other.execute("CREATE TABLE mine (x)");
  }
  EXPECT_THROW(SqliteStore((dir / "other.db").string()), StoreError);
}

// The two-station bug: two processes opening a new file both switch it to WAL; each holds a read
// lock when it asks for the write lock, and SQLite answers one of them BUSY at once, without its
// busy handler (deadlock avoidance). The store retries the switch within its busy deadline.
TEST(SqliteStore, StationsOpeningOneNewDatabaseTogetherAllSucceed) {
  const auto dir = freshDir("store_new_file_together");
  int failures = 0;
  std::string lastError;
  for (int round = 0; round < 40; ++round) {
    const std::string path = (dir / ("s" + std::to_string(round) + ".db")).string();
    std::atomic<int> ready{0};
    std::mutex m;
    auto station = [&] {
      ++ready;
      while (ready < 4) std::this_thread::yield();
      try {
        SqliteStore store(path);
      } catch (const StoreError& e) {
        std::lock_guard<std::mutex> lock(m);
        ++failures;
        lastError = e.what();
      }
    };
    std::vector<std::thread> stations;
    for (int i = 0; i < 4; ++i) stations.emplace_back(station);
    for (auto& t : stations) t.join();
  }
  EXPECT_EQ(failures, 0) << lastError;
}

TEST(SqliteStore, DroppedOutSlotGoesToTheNextNewcomer) {
  const auto dir = freshDir("store_dropout");
  const Experiment e = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  const Design design = makeDesign(e);
  const std::string path = (dir / "s.db").string();
  SqliteStore store(path);
  Database db(path, false);
  auto enrol = [&](const std::string& who) { return store.enrol(e, "test", who, store.nextFreeSlot(e.id), design, {fakeTrial(1)})->slot; };
  EXPECT_EQ(enrol("a"), 0);
  EXPECT_EQ(enrol("b"), 1);
  EXPECT_EQ(enrol("c"), 2);
  store.dropParticipant(e.id, "b", "moved away");
  EXPECT_THROW(store.dropParticipant(e.id, "b", "again"), StoreError);
  EXPECT_EQ(enrol("d"), 1);
  EXPECT_EQ(enrol("e"), 3);
  const auto assignments = store.assignments(e.id);
  ASSERT_EQ(assignments.size(), 5u);
  EXPECT_EQ(assignments[1].participant, "b");
  EXPECT_EQ(assignments[1].status, "dropped");
  EXPECT_EQ(assignments[2].participant, "d");
  EXPECT_EQ(assignments[2].row, 1);
  EXPECT_EQ(store.versions(e.id).size(), 1u);  // the same file is one version
}

TEST(SqliteStore, ATakenSlotWritesNothingAndAKnownParticipantIsRefused) {
  const auto dir = freshDir("store_taken_slot");
  const Experiment e = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  const Design design = makeDesign(e);
  const std::string path = (dir / "s.db").string();
  SqliteStore store(path);
  Database db(path, false);
  ASSERT_TRUE(store.enrol(e, "test", "a", 0, design, {fakeTrial(1)}));
  EXPECT_FALSE(store.enrol(e, "test", "b", 0, design, {fakeTrial(1)}));  // slot 0 is taken: nothing written
  EXPECT_FALSE(store.findParticipant(e.id, "b"));
  EXPECT_THROW(store.enrol(e, "test", "a", 1, design, {fakeTrial(1)}), StoreError);
  Statement count = db.prepare("SELECT (SELECT count(*) FROM participants), (SELECT count(*) FROM trials)");
  ASSERT_TRUE(count.step());
  EXPECT_EQ(count.integer(0), 1);
  EXPECT_EQ(count.integer(1), 1);
}

TEST(SqliteStore, AnEditedFileIsANewVersionAndEverySessionRecordsItsVersion) {
  const auto dir = freshDir("store_versions");
  const Experiment e = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  const Design design = makeDesign(e);
  const std::string path = (dir / "s.db").string();
  SqliteStore store(path);
  Database db(path, false);
  const auto a = *store.enrol(e, "test", "a", 0, design, {fakeTrial(1)});
  const auto first = store.startSession(a.id, e, "test", "simulated");
  Experiment edited = e;
  edited.text += "\n# instructions edited while piloting\n";
  const auto b = *store.enrol(edited, "test", "b", 1, design, {fakeTrial(1)});
  const auto second = store.startSession(b.id, edited, "test", "simulated");
  const auto versions = store.versions(e.id);
  ASSERT_EQ(versions.size(), 2u);
  EXPECT_EQ(versions[0].version, 1);
  EXPECT_EQ(versions[1].version, 2);
  EXPECT_EQ(store.findVersion(edited)->row, versions[1].row);
  Statement s = db.prepare("SELECT experiment FROM sessions WHERE id IN (?1, ?2) ORDER BY id");
  s.bind(1, first).bind(2, second);
  ASSERT_TRUE(s.step());
  EXPECT_EQ(s.integer(0), versions[0].row);
  ASSERT_TRUE(s.step());
  EXPECT_EQ(s.integer(0), versions[1].row);
}

TEST(SqliteStore, ASessionOfALiveProcessIsRefusedAndADeadOneIsResumed) {
  const auto dir = freshDir("store_session_claim");
  const Experiment e = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  const std::string path = (dir / "s.db").string();
  SqliteStore store(path);
  Database db(path, false);
  const auto p = *store.enrol(e, "test", "p", 0, makeDesign(e), {fakeTrial(1)});
  const auto open = store.startSession(p.id, e, "test", "window");  // this process: alive
  EXPECT_THROW(store.startSession(p.id, e, "test", "window"), SessionConflict);
  // The same session as if its process had died (another start time on this host): resumed.
  Statement dead = db.prepare("UPDATE sessions SET process_start = 'not-this-process' WHERE id = ?1");
  dead.bind(1, open).run();
  const auto resumed = store.startSession(p.id, e, "test", "window");
  Statement s = db.prepare("SELECT end_reason, resumed_by, ended_at IS NULL FROM sessions WHERE id = ?1");
  s.bind(1, open);
  ASSERT_TRUE(s.step());
  EXPECT_EQ(s.text(0), "interrupted");
  EXPECT_EQ(s.integer(1), resumed);
  EXPECT_EQ(s.integer(2), 1);  // when it really ended is unknown: left empty
}

TEST(SqliteStore, OnsetsAreCommittedAndCountShowings) {
  OneParticipant t("store_onsets");
  auto& store = t.store;
  auto& db = t.db;
  const auto session = t.session;
  const auto trial = store.trials(t.p.id).at(0).id;
  EXPECT_EQ(store.recordOnset(session, trial, 100, R"({"present_ms":1.5})"), 1);
  EXPECT_EQ(store.recordOnset(session, trial, 200, R"({"present_ms":1.5})"), 2);
  Statement s = db.prepare("SELECT detail FROM events WHERE kind = 'onset' ORDER BY id");
  ASSERT_TRUE(s.step());
  EXPECT_EQ(s.text(0), R"({"present_ms":1.5,"showing":1})");
  ASSERT_TRUE(s.step());
  EXPECT_NE(s.text(0).find("shown again after an interruption"), std::string::npos) << s.text(0);
}

TEST(SqliteStore, OneResponsePerTrial) {
  OneParticipant t("store_unique");
  auto& store = t.store;
  auto& db = t.db;
  const auto& p = t.p;
  const auto session = t.session;
  ResponseRecord r;
  r.trial = store.trials(p.id).at(0).id;
  r.session = session;
  r.rawAnswer = "2";
  store.recordResponse(r);
  EXPECT_THROW(store.recordResponse(r), StoreError);
  EXPECT_TRUE(store.trials(p.id).at(0).answered);
  Statement count = db.prepare("SELECT count(*) FROM responses");
  ASSERT_TRUE(count.step());
  EXPECT_EQ(count.integer(0), 1);
}

TEST(SqliteStore, HostileIdsAndAnswersAreStoredAndExportedIntact) {
  const auto dir = freshDir("store_hostile");
  const Experiment e = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  const Design design = makeDesign(e);
  const auto texts = hostileTexts();
  {
    const std::string path = (dir / "s.db").string();
  SqliteStore store(path);
  Database db(path, false);
    for (std::size_t i = 0; i < texts.size(); ++i) {
      const std::string id = texts[i] + "#" + std::to_string(i);  // ids must differ
      const auto p = *store.enrol(e, "test", id, int(i), design, {fakeTrial(1)});
      const auto session = store.startSession(p.id, e, "test", "simulated");
      ResponseRecord r;
      r.trial = store.trials(p.id).at(0).id;
      r.session = session;
      r.rawAnswer = texts[i];
      r.answered = true;
      r.rtSeconds = 1.5;
      store.recordResponse(r);
      store.recordQuestionnaire(p.id, session, "post", 0, {{texts[i], "3", 3.0}});
    }
  }
  SqliteStore store((dir / "s.db").string(), OpenMode::Read);
  Database db((dir / "s.db").string(), false);
  for (const char* table : {"experiments", "participants", "responses", "trials"}) {
    Statement s = db.prepare(std::string("SELECT count(*) FROM ") + table);
    EXPECT_TRUE(s.step()) << table;  // every table survived
  }
  const StoredExperiment stored = storedExperiment(store);
  exportCsv(store, stored, (dir / "csv").string());
  const auto rows = parseCsv(readText((dir / "csv" / "trials.csv").string()));
  ASSERT_EQ(rows.size(), texts.size() + 1);
  const auto& header = rows[0];
  const auto column = [&](const std::string& name) { return std::size_t(std::find(header.begin(), header.end(), name) - header.begin()); };
  for (std::size_t i = 0; i < texts.size(); ++i) {
    ASSERT_EQ(rows[i + 1].size(), header.size()) << i;
    EXPECT_TRUE(rows[i + 1][column("participant")] == texts[i] + "#" + std::to_string(i)) << "participant " << i;
    EXPECT_TRUE(rows[i + 1][column("raw_answer")] == texts[i]) << "answer " << i;
    EXPECT_EQ(rows[i + 1][column("rt_seconds")], "1.5");
  }
  const auto q = parseCsv(readText((dir / "csv" / "questionnaires.csv").string()));
  ASSERT_EQ(q.size(), texts.size() + 1);
  for (std::size_t i = 0; i < texts.size(); ++i) EXPECT_TRUE(q[i + 1][4] == texts[i]) << "item " << i;
}

TEST(CsvExport, QuotesOnlyWhatNeedsIt) {
  EXPECT_EQ(csvField("plain"), "plain");
  EXPECT_EQ(csvField("a,b"), "\"a,b\"");
  EXPECT_EQ(csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csvField("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csvField(" padded"), "\" padded\"");
}
