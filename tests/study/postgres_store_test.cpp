// The PostgreSQL store's own behaviour, on a real server (this test process's throw-away cluster):
// the schema created once and foreign or newer databases refused, stations and server threads
// enrolling at once (every slot exactly once, one response per trial), a server that goes away
// mid-study (the failing call says so, the next one reconnects, nothing acknowledged is lost),
// readers that never write, connection errors as one line without the password.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <thread>

#include "study/design/experiment_file.hpp"
#include "study/store/open_store.hpp"
#include "study/store/postgres_connection.hpp"
#include "study/store/postgres_store.hpp"
#include "tests/study/store_backends.hpp"
#include "tests/study/store_test_support.hpp"
#include "tests/study/study_test_support.hpp"

using namespace tlab::study;
using tlab::testing::fakeTrial;
using tlab::testing::sharedPostgresCluster;

namespace {

std::string peek(const std::string& url, const std::string& sql) { return tlab::testing::storeBackend("postgres").peek(url, sql); }
void execute(const std::string& url, const std::string& sql) { tlab::testing::storeBackend("postgres").execute(url, sql); }

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const StoreError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(PostgresStore, TheSchemaIsCreatedOnceAndForeignOrNewerDatabasesAreRefused) {
  const std::string url = sharedPostgresCluster().createDatabase("schema");
  { PostgresStore store(url); }
  EXPECT_EQ(peek(url, "SELECT max(version) FROM schema_migrations"), "4");
  EXPECT_EQ(peek(url, "SELECT count(*) FROM schema_migrations"), "1");
  { PostgresStore again(url); }  // reopening keeps the schema
  EXPECT_EQ(peek(url, "SELECT count(*) FROM schema_migrations"), "1");

  const std::string foreign = sharedPostgresCluster().createDatabase("foreign");
  execute(foreign, "CREATE TABLE mine (x integer)");
  const std::string refused = errorOf([&] { PostgresStore store(foreign); });
  EXPECT_NE(refused.find("not a tlab study database (it has other tables: mine)"), std::string::npos) << refused;
  EXPECT_EQ(peek(foreign, "SELECT count(*) FROM information_schema.tables WHERE table_schema = 'public'"), "1");  // untouched

  execute(url, "INSERT INTO schema_migrations VALUES (99, 'from the future', 'then')");
  const std::string newer = errorOf([&] { PostgresStore store(url, OpenMode::Read); });
  EXPECT_NE(newer.find("written by a newer tlab (schema version 99"), std::string::npos) << newer;
}

TEST(PostgresStore, StationsOpeningOneNewDatabaseTogetherCreateItOnce) {
  const std::string url = sharedPostgresCluster().createDatabase("together");
  std::atomic<int> failures{0};
  std::vector<std::thread> stations;
  for (int i = 0; i < 6; ++i)
    stations.emplace_back([&] {
      try {
        PostgresStore store(url);
      } catch (const StoreError&) {
        ++failures;
      }
    });
  for (auto& t : stations) t.join();
  EXPECT_EQ(failures, 0);
  EXPECT_EQ(peek(url, "SELECT count(*) FROM schema_migrations"), "1");
}

// Server threads and stations enrolling newcomers at once, each on its own connection: every
// slot goes to exactly one participant; two stations answering one trial: one response.
TEST(PostgresStore, ConcurrentEnrolmentGivesEverySlotExactlyOnce) {
  const std::string url = sharedPostgresCluster().createDatabase("concurrent");
  const Experiment e = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  const Design design = makeDesign(e);
  { PostgresStore create(url); }
  constexpr int kThreads = 8, kEach = 6;
  std::atomic<int> ready{0}, taken{0};
  std::mutex m;
  std::vector<std::string> errors;
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i)
    threads.emplace_back([&, i] {
      try {
        PostgresStore store(url);
        ++ready;
        while (ready < kThreads) std::this_thread::yield();
        for (int k = 0; k < kEach; ++k) {
          const std::string who = "p" + std::to_string(i) + "-" + std::to_string(k);
          while (!store.enrol(e, "test", who, store.nextFreeSlot(e.id), design, {fakeTrial(1), fakeTrial(2)})) ++taken;
        }
      } catch (const std::exception& ex) {
        std::lock_guard<std::mutex> lock(m);
        errors.push_back(ex.what());
      }
    });
  for (auto& t : threads) t.join();
  ASSERT_TRUE(errors.empty()) << errors.front();
  PostgresStore store(url, OpenMode::Read);
  const auto assignments = store.assignments(e.id);
  ASSERT_EQ(assignments.size(), std::size_t(kThreads * kEach));
  std::set<int> slots;
  for (const auto& a : assignments) slots.insert(a.slot);
  EXPECT_EQ(slots.size(), std::size_t(kThreads * kEach));
  EXPECT_EQ(*slots.rbegin(), kThreads * kEach - 1);
  EXPECT_EQ(peek(url, "SELECT count(*) FROM trials"), std::to_string(2 * kThreads * kEach));  // no plan of a refused enrolment
  std::cout << "slots taken by another thread in the meantime (retried): " << taken << "\n";

  // Four connections answer the same trial at once: exactly one response is stored.
  PostgresStore writer(url);
  const auto p = *writer.findParticipant(e.id, "p0-0");
  ResponseRecord r;
  r.trial = writer.trials(p.id).at(0).id;
  r.session = writer.startSession(p.id, e, "test", "simulated");
  std::atomic<int> stored{0}, refused{0};
  std::vector<std::thread> answers;
  for (int i = 0; i < 4; ++i)
    answers.emplace_back([&] {
      PostgresStore station(url);
      try {
        station.recordResponse(r);
        ++stored;
      } catch (const StoreError& ex) {
        if (std::string(ex.what()).find("already has a response") != std::string::npos) ++refused;
      }
    });
  for (auto& t : answers) t.join();
  EXPECT_EQ(stored, 1);
  EXPECT_EQ(refused, 3);
  EXPECT_EQ(peek(url, "SELECT count(*) FROM responses WHERE trial = " + std::to_string(r.trial)), "1");
}

TEST(PostgresStore, ALostServerFailsTheCallAndTheNextCallReconnects) {
  auto& cluster = sharedPostgresCluster();
  const std::string url = cluster.createDatabase("lost");
  const Experiment e = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  PostgresStore store(url);
  const auto p = *store.enrol(e, "test", "p", 0, makeDesign(e), {fakeTrial(1), fakeTrial(2)});
  const auto session = store.startSession(p.id, e, "test", "simulated");
  const auto plan = store.trials(p.id);
  ResponseRecord first;
  first.trial = plan.at(0).id;
  first.session = session;
  first.rawAnswer = "1";
  store.recordResponse(first);  // acknowledged before the server goes away

  cluster.stop();
  ResponseRecord second = first;
  second.trial = plan.at(1).id;
  second.rawAnswer = "2";
  const std::string lost = errorOf([&] { store.recordResponse(second); });
  EXPECT_NE(lost.find("the answer was not stored"), std::string::npos) << lost;
  EXPECT_EQ(lost.find('\n'), std::string::npos) << lost;
  const std::string down = errorOf([&] { store.recordResponse(second); });  // still down: cannot connect, one line
  EXPECT_NE(down.find("cannot connect to PostgreSQL at postgresql:///lost"), std::string::npos) << down;

  cluster.start();
  store.recordResponse(second);  // reconnects
  const auto after = store.trials(p.id);
  EXPECT_TRUE(after.at(0).answered);
  EXPECT_TRUE(after.at(1).answered);
  EXPECT_EQ(peek(url, "SELECT string_agg(raw_answer, ',' ORDER BY trial) FROM responses"), "1,2");
}

TEST(PostgresStore, ReadersNeverWrite) {
  const std::string url = sharedPostgresCluster().createDatabase("readers");
  const std::string empty = errorOf([&] { PostgresStore store(url, OpenMode::Read); });
  EXPECT_NE(empty.find("an empty database"), std::string::npos) << empty;
  EXPECT_EQ(peek(url, "SELECT count(*) FROM information_schema.tables WHERE table_schema = 'public'"), "0");  // no schema made
  const Experiment e = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  { PostgresStore writer(url); }
  PostgresStore reader(url, OpenMode::Read);
  const std::string refused = errorOf([&] { reader.enrol(e, "test", "p", 0, makeDesign(e), {fakeTrial(1)}); });
  EXPECT_NE(refused.find("read-only transaction"), std::string::npos) << refused;
  EXPECT_EQ(peek(url, "SELECT count(*) FROM participants"), "0");
}

TEST(PostgresStore, ConnectionErrorsAreOneLineWithoutThePassword) {
  auto& cluster = sharedPostgresCluster();
  const std::string nowhere = "postgresql://ann:s3cret@/study?host=/nonexistent-tlab-socket-dir&port=5999";
  const std::string unreachable = errorOf([&] { openStore(nowhere); });
  EXPECT_EQ(unreachable.rfind("cannot connect to PostgreSQL at postgresql://ann@/study?host=/nonexistent-tlab-socket-dir&port=5999: ", 0), 0u)
      << unreachable;
  EXPECT_EQ(unreachable.find("s3cret"), std::string::npos) << unreachable;
  EXPECT_EQ(unreachable.find('\n'), std::string::npos) << unreachable;
  const std::string noDatabase = errorOf([&] { openStore(cluster.url("no_such_db")); });
  EXPECT_NE(noDatabase.find("database \"no_such_db\" does not exist"), std::string::npos) << noDatabase;
  std::string wrongUser = cluster.url("postgres");
  wrongUser.replace(wrongUser.find("user=tlab"), 9, "user=mallory&password=hunter2");
  const std::string refused = errorOf([&] { openStore(wrongUser); });
  EXPECT_NE(refused.find("role \"mallory\" does not exist"), std::string::npos) << refused;
  EXPECT_EQ(refused.find("hunter2"), std::string::npos) << refused;
  EXPECT_EQ(redactedUrl("postgresql://ann:pw@db.example.org:5432/study?sslmode=require&password=x"),
            "postgresql://ann@db.example.org:5432/study?sslmode=require");
  EXPECT_EQ(redactedUrl("postgres://db/study"), "postgres://db/study");
}

TEST(PostgresStore, InvalidUtf8IsRefusedAndNothingIsWritten) {
  const std::string url = sharedPostgresCluster().createDatabase("utf8");
  const Experiment e = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  PostgresStore store(url);
  const std::string refused = errorOf([&] { store.enrol(e, "test", tlab::testing::invalidUtf8Text(), 0, makeDesign(e), {fakeTrial(1)}); });
  EXPECT_NE(refused.find("invalid byte sequence for encoding \"UTF8\""), std::string::npos) << refused;
  EXPECT_EQ(refused.find('\n'), std::string::npos) << refused;
  EXPECT_EQ(peek(url, "SELECT count(*) FROM participants"), "0");
}
