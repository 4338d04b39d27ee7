// The Store contract on both stores (SQLite and PostgreSQL): slots re-assigned after a dropout, a
// taken slot writes nothing, versions, sessions of live and dead stations, onsets, one response
// per trial, live frames read back per trial, and hostile participant ids and answers (quotes, SQL, 1 MB) stored and exported byte
// for byte. SQLite-only behaviour (file header, WAL): sqlite_store_test.cpp; PostgreSQL-only
// (concurrency, lost server, read-only readers): postgres_store_test.cpp.
#include <unistd.h>

#include <gtest/gtest.h>

#include "study/design/experiment_file.hpp"
#include "study/store/csv_export.hpp"
#include "study/store/open_store.hpp"
#include "study/store/study_table.hpp"
#include "tests/study/store_backends.hpp"
#include "tests/study/store_test_support.hpp"
#include "tests/study/study_test_support.hpp"

using namespace tlab::study;
using tlab::testing::fakeTrial;
using tlab::testing::hostileTexts;
using tlab::testing::parseCsv;
using tlab::testing::readText;

namespace {

class StoreContract : public ::testing::TestWithParam<std::string> {
 protected:
  tlab::testing::StoreBackend& backend() { return tlab::testing::storeBackend(GetParam()); }
  std::string fresh(const std::string& name) { return backend().freshLocation(name + "_" + GetParam()); }
  std::string peek(const std::string& location, const std::string& sql) { return backend().peek(location, sql); }
  const Experiment e = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  const Design design = makeDesign(e);
};

INSTANTIATE_TEST_SUITE_P(Stores, StoreContract, ::testing::Values("sqlite", "postgres"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace

TEST_P(StoreContract, DroppedOutSlotGoesToTheNextNewcomer) {
  const auto store = openStore(fresh("store_dropout"));
  auto enrol = [&](const std::string& who) { return store->enrol(e, "test", who, store->nextFreeSlot(e.id), design, {fakeTrial(1)})->slot; };
  EXPECT_EQ(enrol("a"), 0);
  EXPECT_EQ(enrol("b"), 1);
  EXPECT_EQ(enrol("c"), 2);
  store->dropParticipant(e.id, "b", "moved away");
  EXPECT_THROW(store->dropParticipant(e.id, "b", "again"), StoreError);
  EXPECT_EQ(enrol("d"), 1);
  EXPECT_EQ(enrol("e"), 3);
  const auto assignments = store->assignments(e.id);
  ASSERT_EQ(assignments.size(), 5u);
  EXPECT_EQ(assignments[1].participant, "b");
  EXPECT_EQ(assignments[1].status, "dropped");
  EXPECT_EQ(assignments[2].participant, "d");
  EXPECT_EQ(assignments[2].row, 1);
  EXPECT_EQ(store->versions(e.id).size(), 1u);  // the same file is one version
}

TEST_P(StoreContract, ATakenSlotWritesNothingAndAKnownParticipantIsRefused) {
  const std::string location = fresh("store_taken_slot");
  const auto store = openStore(location);
  ASSERT_TRUE(store->enrol(e, "test", "a", 0, design, {fakeTrial(1)}));
  EXPECT_FALSE(store->enrol(e, "test", "b", 0, design, {fakeTrial(1)}));  // slot 0 is taken: nothing written
  EXPECT_FALSE(store->findParticipant(e.id, "b"));
  EXPECT_THROW(store->enrol(e, "test", "a", 1, design, {fakeTrial(1)}), StoreError);
  EXPECT_EQ(peek(location, "SELECT count(*) FROM participants"), "1");
  EXPECT_EQ(peek(location, "SELECT count(*) FROM trials"), "1");
}

TEST_P(StoreContract, AnEditedFileIsANewVersionAndEverySessionRecordsItsVersion) {
  const std::string location = fresh("store_versions");
  const auto store = openStore(location);
  const auto a = *store->enrol(e, "test", "a", 0, design, {fakeTrial(1)});
  const auto first = store->startSession(a.id, e, "test", "simulated");
  Experiment edited = e;
  edited.text += "\n# instructions edited while piloting\n";
  const auto b = *store->enrol(edited, "test", "b", 1, design, {fakeTrial(1)});
  const auto second = store->startSession(b.id, edited, "test", "simulated");
  const auto versions = store->versions(e.id);
  ASSERT_EQ(versions.size(), 2u);
  EXPECT_EQ(versions[0].version, 1);
  EXPECT_EQ(versions[1].version, 2);
  EXPECT_EQ(store->findVersion(edited)->row, versions[1].row);
  EXPECT_EQ(peek(location, "SELECT experiment FROM sessions WHERE id = " + std::to_string(first)), std::to_string(versions[0].row));
  EXPECT_EQ(peek(location, "SELECT experiment FROM sessions WHERE id = " + std::to_string(second)), std::to_string(versions[1].row));
}

TEST_P(StoreContract, ASessionOfALiveProcessIsRefusedAndADeadOneIsResumed) {
  const std::string location = fresh("store_session_claim");
  const auto store = openStore(location);
  const auto p = *store->enrol(e, "test", "p", 0, design, {fakeTrial(1)});
  const auto left = store->startSession(p.id, e, "test", "browser");
  // A session this process left open (its flow stopped on a storage error; tlab serve walks one
  // flow per participant) does not block this process: it is resumed.
  const auto open = store->startSession(p.id, e, "test", "browser");
  EXPECT_EQ(peek(location, "SELECT resumed_by FROM sessions WHERE id = " + std::to_string(left)), std::to_string(open));
  // Another live process's session is refused: the parent process (alive) as its station.
  const std::string station = stationName().substr(0, stationName().rfind(':') + 1) + std::to_string(::getppid());
  backend().execute(location, "UPDATE sessions SET station = '" + station + "', process_start = '' WHERE id = " + std::to_string(open));
  EXPECT_THROW(store->startSession(p.id, e, "test", "window"), SessionConflict);
  // The same session as if its process had died (another start time on this host): resumed.
  backend().execute(location, "UPDATE sessions SET process_start = 'not-this-process' WHERE id = " + std::to_string(open));
  const auto resumed = store->startSession(p.id, e, "test", "window");
  const std::string where = " FROM sessions WHERE id = " + std::to_string(open);
  EXPECT_EQ(peek(location, "SELECT end_reason" + where), "interrupted");
  EXPECT_EQ(peek(location, "SELECT resumed_by" + where), std::to_string(resumed));
  EXPECT_EQ(peek(location, "SELECT count(*)" + where + " AND ended_at IS NULL"), "1");  // when it really ended is unknown
}

TEST_P(StoreContract, EventsOfOneCallAreStoredInOrderWithTheirTrial) {
  const std::string location = fresh("store_events_batch");
  const auto store = openStore(location);
  const auto p = *store->enrol(e, "test", "p", 0, design, {fakeTrial(1)});
  const auto trial = store->trials(p.id).at(0).id;
  const auto session = store->startSession(p.id, e, "test", "window");
  std::vector<EventRecord> frames;
  for (int i = 0; i < 50; ++i) frames.push_back({1000 + i, "frame", R"({"index":)" + std::to_string(i) + "}"});
  store->recordEvents(session, trial, frames);
  store->recordEvents(session, std::nullopt, {});  // nothing: no transaction, no row
  EXPECT_EQ(peek(location, "SELECT count(*) FROM events WHERE kind = 'frame' AND trial = " + std::to_string(trial)), "50");
  EXPECT_EQ(peek(location, "SELECT detail FROM events WHERE kind = 'frame' ORDER BY id LIMIT 1"), R"({"index":0})");
  EXPECT_EQ(peek(location, "SELECT detail FROM events WHERE kind = 'frame' ORDER BY id DESC LIMIT 1"), R"({"index":49})");
  EXPECT_EQ(peek(location, "SELECT t_ns FROM events WHERE kind = 'frame' ORDER BY id DESC LIMIT 1"), "1049");
}

TEST_P(StoreContract, TheNewestEventOfAKindOverAParticipantsSessions) {
  const auto store = openStore(fresh("store_last_event"));
  const auto p = *store->enrol(e, "test", "p", 0, design, {fakeTrial(1)});
  const auto q = *store->enrol(e, "test", "q", 1, design, {fakeTrial(1)});
  EXPECT_FALSE(store->lastEventDetail(p.id, "calibration"));
  const auto first = store->startSession(p.id, e, "test", "browser");
  store->recordEvent(first, std::nullopt, 1, "calibration", R"({"px_per_cm":37.5})");
  store->recordEvent(first, std::nullopt, 2, "consent", "{}");
  store->endSession(first, "closed");
  const auto other = store->startSession(q.id, e, "test", "browser");
  store->recordEvent(other, std::nullopt, 3, "calibration", R"({"px_per_cm":99})");
  EXPECT_EQ(store->lastEventDetail(p.id, "calibration"), R"({"px_per_cm":37.5})");
  const auto second = store->startSession(p.id, e, "test", "browser");
  store->recordEvent(second, std::nullopt, 4, "calibration", R"({"px_per_cm":40.25})");
  EXPECT_EQ(store->lastEventDetail(p.id, "calibration"), R"({"px_per_cm":40.25})");
  EXPECT_EQ(store->lastEventDetail(q.id, "calibration"), R"({"px_per_cm":99})");
  EXPECT_FALSE(store->lastEventDetail(p.id, "no-such-kind"));
}

TEST_P(StoreContract, OnsetsAreCommittedAndCountShowings) {
  const std::string location = fresh("store_onsets");
  const auto store = openStore(location);
  const auto p = *store->enrol(e, "test", "p", 0, design, {fakeTrial(1)});
  const auto session = store->startSession(p.id, e, "test", "simulated");
  const auto trial = store->trials(p.id).at(0).id;
  EXPECT_EQ(store->recordOnset(session, trial, 100, R"({"present_ms":1.5})"), 1);
  EXPECT_EQ(store->recordOnset(session, trial, 200, R"({"present_ms":1.5})"), 2);
  EXPECT_EQ(peek(location, "SELECT detail FROM events WHERE kind = 'onset' ORDER BY id"), R"({"present_ms":1.5,"showing":1})");
  const std::string second = peek(location, "SELECT detail FROM events WHERE kind = 'onset' ORDER BY id DESC");
  EXPECT_NE(second.find("shown again after an interruption"), std::string::npos) << second;
}

TEST_P(StoreContract, LiveFramesAreReadBackPerTrialInTheOrderStored) {
  const std::string location = fresh("store_frames");
  const auto store = openStore(location);
  const auto p = *store->enrol(e, "test", "p'1", 0, design, {fakeTrial(1), fakeTrial(2)});
  const auto session = store->startSession(p.id, e, "test", "window");
  const auto trials = store->trials(p.id);
  store->recordEvent(session, trials.at(1).id, 300, "frame", R"({"index":0})");
  store->recordEvent(session, trials.at(1).id, 310, "camera", "eye=1,2,3");
  store->recordEvent(session, trials.at(1).id, 320, "frame", R"({"index":1})");
  store->recordEvent(session, trials.at(0).id, 100, "onset", "{}");
  const DataTable live = store->liveTrials(e.id);
  ASSERT_EQ(live.rows.size(), 1u);
  EXPECT_EQ(live.rows[0], (std::vector<std::string>{"p'1", std::to_string(trials.at(1).sequence), trials.at(1).phase, trials.at(1).taskId, "2"}));
  const DataTable frames = store->trialFrames(trials.at(1).id);
  const std::string s = std::to_string(session);
  EXPECT_EQ(frames.rows, (std::vector<std::vector<std::string>>{{s, "300", R"({"index":0})"}, {s, "320", R"({"index":1})"}}));
  EXPECT_TRUE(store->trialFrames(trials.at(0).id).rows.empty());
}

TEST_P(StoreContract, OneResponsePerTrial) {
  const std::string location = fresh("store_unique");
  const auto store = openStore(location);
  const auto p = *store->enrol(e, "test", "p", 0, design, {fakeTrial(1)});
  ResponseRecord r;
  r.trial = store->trials(p.id).at(0).id;
  r.session = store->startSession(p.id, e, "test", "simulated");
  r.rawAnswer = "2";
  store->recordResponse(r);
  EXPECT_THROW(store->recordResponse(r), StoreError);
  EXPECT_TRUE(store->trials(p.id).at(0).answered);
  EXPECT_EQ(peek(location, "SELECT count(*) FROM responses"), "1");
  EXPECT_EQ(peek(location, "SELECT count(*) FROM events WHERE kind = 'response'"), "1");  // the refused one wrote no event
}

TEST_P(StoreContract, HostileIdsAndAnswersAreStoredAndExportedIntact) {
  const std::string location = fresh("store_hostile");
  const auto dir = tlab::testing::freshDir("store_hostile_csv_" + GetParam());
  // PostgreSQL's UTF8 databases refuse invalid UTF-8 (postgres_store_test.cpp); every other text is stored as is.
  const auto texts = hostileTexts(GetParam() == "sqlite");
  {
    const auto store = openStore(location);
    for (std::size_t i = 0; i < texts.size(); ++i) {
      const std::string id = texts[i] + "#" + std::to_string(i);  // ids must differ
      const auto p = *store->enrol(e, "test", id, int(i), design, {fakeTrial(1)});
      const auto session = store->startSession(p.id, e, "test", "simulated");
      ResponseRecord r;
      r.trial = store->trials(p.id).at(0).id;
      r.session = session;
      r.rawAnswer = texts[i];
      r.answered = true;
      r.rtSeconds = 1.5;
      store->recordResponse(r);
      store->recordQuestionnaire(p.id, session, "post", 0, {{texts[i], "3", 3.0}});
    }
  }
  const auto store = openStore(location, OpenMode::Read);
  for (const char* table : {"experiments", "participants", "responses", "trials"})
    EXPECT_NE(peek(location, std::string("SELECT count(*) FROM ") + table), "") << table;  // every table survived
  exportCsv(*store, storedExperiment(*store), (dir / "csv").string());
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
  for (std::size_t i = 0; i < texts.size(); ++i) {
    EXPECT_TRUE(q[i + 1][4] == texts[i]) << "item " << i;
    EXPECT_EQ(q[i + 1][6], "3.0") << "value " << i;  // REAL values read as SQLite writes them
  }
}
