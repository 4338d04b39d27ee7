// The SQLite store: schema version and WAL, slots re-assigned after a dropout, one response per
// trial, and hostile participant ids and answers (quotes, SQL, 1 MB, invalid UTF-8) stored and
// exported byte for byte.
#include <gtest/gtest.h>

#include <filesystem>

#include "study/csv_export.hpp"
#include "study/experiment_file.hpp"
#include "study/session_store.hpp"
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

}  // namespace

TEST(SessionStore, SchemaVersionAndWal) {
  const auto dir = freshDir("store_schema");
  const std::string path = (dir / "s.db").string();
  {
    SessionStore store(path);
    EXPECT_EQ(store.database().userVersion(), SessionStore::kSchemaVersion);
    Statement mode = store.database().prepare("PRAGMA journal_mode");
    ASSERT_TRUE(mode.step());
    EXPECT_EQ(mode.text(0), "wal");
  }
  SessionStore again(path);  // reopening keeps the schema
  EXPECT_EQ(again.database().userVersion(), SessionStore::kSchemaVersion);
  {
    Database other((dir / "other.db").string(), true);
    other.execute("CREATE TABLE mine (x)");
  }
  EXPECT_THROW(SessionStore((dir / "other.db").string()), StoreError);
}

TEST(SessionStore, DroppedOutSlotGoesToTheNextNewcomer) {
  const auto dir = freshDir("store_dropout");
  const Experiment e = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  const Design design = makeDesign(e);
  SessionStore store((dir / "s.db").string());
  const auto row = store.registerExperiment(e, "test");
  EXPECT_EQ(store.registerExperiment(e, "test"), row);
  EXPECT_EQ(store.enrol(row, "a", design).slot, 0);
  EXPECT_EQ(store.enrol(row, "b", design).slot, 1);
  EXPECT_EQ(store.enrol(row, "c", design).slot, 2);
  store.dropParticipant(row, "b", "moved away");
  EXPECT_THROW(store.dropParticipant(row, "b", "again"), StoreError);
  EXPECT_EQ(store.enrol(row, "d", design).slot, 1);
  EXPECT_EQ(store.enrol(row, "e", design).slot, 3);
  const auto assignments = store.assignments(row);
  ASSERT_EQ(assignments.size(), 5u);
  EXPECT_EQ(assignments[1].participant, "b");
  EXPECT_EQ(assignments[1].status, "dropped");
  EXPECT_EQ(assignments[2].participant, "d");
  EXPECT_EQ(assignments[2].row, 1);
  Experiment changed = e;
  changed.text += "\n# edited\n";
  EXPECT_THROW(store.registerExperiment(changed, "test"), StoreError);
}

TEST(SessionStore, OneResponsePerTrial) {
  const auto dir = freshDir("store_unique");
  const Experiment e = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  SessionStore store((dir / "s.db").string());
  const auto row = store.registerExperiment(e, "test");
  const auto p = store.enrol(row, "p", makeDesign(e));
  store.insertTrials(p.id, {fakeTrial(1)});
  const auto session = store.startSession(p.id, "simulated");
  ResponseRecord r;
  r.trial = store.trials(p.id).at(0).id;
  r.session = session;
  r.rawAnswer = "2";
  store.recordResponse(r);
  EXPECT_THROW(store.recordResponse(r), StoreError);
  EXPECT_TRUE(store.trials(p.id).at(0).answered);
  Statement count = store.database().prepare("SELECT count(*) FROM responses");
  ASSERT_TRUE(count.step());
  EXPECT_EQ(count.integer(0), 1);
}

TEST(SessionStore, HostileIdsAndAnswersAreStoredAndExportedIntact) {
  const auto dir = freshDir("store_hostile");
  const Experiment e = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  const Design design = makeDesign(e);
  const auto texts = hostileTexts();
  {
    SessionStore store((dir / "s.db").string());
    const auto row = store.registerExperiment(e, "test");
    for (std::size_t i = 0; i < texts.size(); ++i) {
      const std::string id = texts[i] + "#" + std::to_string(i);  // ids must differ
      const auto p = store.enrol(row, id, design);
      store.insertTrials(p.id, {fakeTrial(1)});
      const auto session = store.startSession(p.id, "simulated");
      ResponseRecord r;
      r.trial = store.trials(p.id).at(0).id;
      r.session = session;
      r.rawAnswer = texts[i];
      r.answered = true;
      r.rtSeconds = 1.5;
      store.recordResponse(r);
      store.recordQuestionnaire(p.id, session, "post", 0, {{texts[i], 3}});
    }
  }
  SessionStore store((dir / "s.db").string(), false);
  for (const char* table : {"experiments", "participants", "responses", "trials"}) {
    Statement s = store.database().prepare(std::string("SELECT count(*) FROM ") + table);
    EXPECT_TRUE(s.step()) << table;  // every table survived
  }
  const StoredExperiment stored{*store.findExperiment("tiny"), e};
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
