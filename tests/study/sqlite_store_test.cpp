// The SQLite store's own behaviour: schema version and WAL, stations opening one new file together,
// and CSV quoting. The Store contract both stores keep (slots, versions, sessions, onsets, one
// response per trial, hostile texts): store_contract_test.cpp.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <filesystem>
#include <thread>

#include "study/store/csv_export.hpp"
#include "study/store/sqlite_store.hpp"
#include "study/store/store_tables.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::study;
using tlab::testing::freshDir;

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

TEST(CsvExport, QuotesOnlyWhatNeedsIt) {
  EXPECT_EQ(csvField("plain"), "plain");
  EXPECT_EQ(csvField("a,b"), "\"a,b\"");
  EXPECT_EQ(csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csvField("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csvField(" padded"), "\" padded\"");
}

// The PostgreSQL store writes REAL cells with storedRealText: it must be SQLite's own text.
TEST(SqliteStore, StoredRealTextIsTheTextSqliteGivesARealColumn) {
  Database db(":memory:", OpenMode::Create);
  db.execute("CREATE TABLE t (id INTEGER PRIMARY KEY, v REAL)");
  const double values[] = {3.0, 0.1, 1e20, -0.0, 1.0 / 3, 123456789012.0, 2.5e-7, 1e15, 1e16, -7.25, 4.9e-324, 1.7976931348623157e308};
  Statement insert = db.prepare("INSERT INTO t (v) VALUES (?1)");
  for (const double v : values) insert.bind(1, v).run();
  Statement s = db.prepare("SELECT v FROM t ORDER BY id");
  for (const double v : values) {
    ASSERT_TRUE(s.step());
    EXPECT_EQ(storedRealText(v), s.text(0)) << v;
  }
}
