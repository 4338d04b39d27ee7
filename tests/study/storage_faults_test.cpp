// Fault injection on the study database, end to end through `tlab simulate` as a user runs it:
// a full disk (a tiny tmpfs), a read-only file (chattr +i: plain chmod does not stop root), a
// write lock held by another process, a truncated file, a file from a newer tlab, and a database
// from the schema-1 tlab (migrated). Each fault gives one clear line and exit 1; every response
// acknowledged before it stays stored exactly once, and a later --resume completes the study.
// Mount and chattr need root (CAP_SYS_ADMIN / CAP_LINUX_IMMUTABLE); those tests skip without it.
#include <gtest/gtest.h>

#include <sys/mount.h>

#include <filesystem>
#include <map>

#include "study/store/schema_migrations.hpp"
#include "study/store/sqlite_store.hpp"
#include "study/store/sqlite_database.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;
using tlab::study::Database;

namespace {

const std::string kTlab = TLAB_EXE;
constexpr int kTrialsPerParticipant = 12;  // crash.toml: 4 blocks × 3 questions

CommandResult simulate(const std::string& db, int participants) {
  return runCommand(kTlab + " simulate " + studyData("crash.toml") + " --participants " + std::to_string(participants) + " --db " +
                    tlab::testing::quoted(db) + " --resume --trials");
}

void expectOneLineError(const CommandResult& r, const std::string& part) {
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_EQ(r.err.rfind("tlab: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
}

// (participant, sequence) → raw answer of every stored response; counts trials with != 1 response.
std::map<std::pair<std::string, int>, std::string> storedAnswers(const std::string& db, int* notOnce = nullptr) {
  Database d(db, false);
  auto s = d.prepare(
      "SELECT p.participant, t.sequence, coalesce(r.raw_answer, '(missing)'), "
      "(SELECT count(*) FROM responses r2 WHERE r2.trial = t.id) FROM trials t JOIN participants p ON p.id = t.participant "
      "JOIN responses r ON r.trial = t.id");
  std::map<std::pair<std::string, int>, std::string> out;
  if (notOnce) *notOnce = 0;
  while (s.step()) {
    out[{s.text(0), int(s.integer(1))}] = s.text(2);
    if (notOnce && s.integer(3) != 1) ++*notOnce;
  }
  return out;
}

std::string integrity(const std::string& db) {
  Database d(db, false);
  auto s = d.prepare("PRAGMA integrity_check");
  return s.step() ? s.text(0) : "";
}

// Every acknowledged response in `out` is stored with the acknowledged answer.
void expectAcknowledgedStored(const std::string& out, const std::string& db) {
  const auto stored = storedAnswers(db);
  for (const auto& a : parseAcks(out)) {
    const auto it = stored.find({a.participant, a.sequence});
    ASSERT_NE(it, stored.end()) << "acknowledged response lost: " << a.participant << " #" << a.sequence;
    EXPECT_EQ(it->second, a.answer) << a.participant << " #" << a.sequence;
  }
}

// The study of `participants` completed: every trial answered exactly once, nothing else.
void expectComplete(const std::string& db, int participants) {
  int notOnce = -1;
  EXPECT_EQ(storedAnswers(db, &notOnce).size(), std::size_t(participants * kTrialsPerParticipant));
  EXPECT_EQ(notOnce, 0);
  EXPECT_EQ(integrity(db), "ok");
}

// A tmpfs of `kib` KiB mounted on `dir` for the life of the object.
class TinyFilesystem {
 public:
  TinyFilesystem(const std::filesystem::path& dir, int kib) : dir_(dir) {
    std::filesystem::create_directories(dir);
    mounted_ = ::mount("tlab-test", dir.c_str(), "tmpfs", 0, ("size=" + std::to_string(kib) + "k").c_str()) == 0;
  }
  ~TinyFilesystem() {
    if (mounted_) ::umount2(dir_.c_str(), MNT_DETACH);
  }
  bool mounted() const { return mounted_; }

 private:
  std::filesystem::path dir_;
  bool mounted_ = false;
};

// chattr +i on `file` for the life of the object (root cannot write an immutable file).
class ImmutableFile {
 public:
  explicit ImmutableFile(const std::string& file) : file_(file) {
    ok_ = runCommand("chattr +i " + tlab::testing::quoted(file) + " 2>&1").exitCode == 0;
  }
  ~ImmutableFile() { release(); }
  void release() {
    if (ok_) runCommand("chattr -i " + tlab::testing::quoted(file_));
    ok_ = false;
  }
  bool ok() const { return ok_; }

 private:
  std::string file_;
  bool ok_ = false;
};

}  // namespace

TEST(StorageFaults, FullDiskStopsCleanlyAndResumeCompletes) {
  const auto dir = freshDir("fault_disk_full") / "disk";
  TinyFilesystem disk(dir, 8192);  // room for the write-ahead log (up to 1000 pages before a checkpoint)
  if (!disk.mounted()) GTEST_SKIP() << "needs root to mount a tmpfs";
  const std::string db = (dir / "study.db").string();
  ASSERT_EQ(simulate(db, 1).exitCode, 0);
  // Fill the disk, leaving 112 KiB: room for the write-ahead log index (32 KiB), the next
  // participant's plan and a few responses; the disk fills up inside that session.
  runCommand("dd if=/dev/zero of=" + tlab::testing::quoted((dir / "filler").string()) + " bs=4k 2>/dev/null; truncate -s -112k " +
             tlab::testing::quoted((dir / "filler").string()));
  const auto full = simulate(db, 3);
  expectOneLineError(full, "is full: free space, then continue with --resume");
  EXPECT_NE(full.err.find("participant 'sim-002': session stopped, trial "), std::string::npos) << full.err;
  expectAcknowledgedStored(full.out, db);
  std::filesystem::remove(dir / "filler");
  const auto resumed = simulate(db, 3);
  ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
  expectAcknowledgedStored(full.out, db);
  expectComplete(db, 3);
}

TEST(StorageFaults, ReadOnlyDatabaseIsReadableNotWritableAndResumeCompletes) {
  const auto dir = freshDir("fault_read_only");
  const std::string db = (dir / "study.db").string();
  ASSERT_EQ(simulate(db, 1).exitCode, 0);
  const std::string before = readText(db);
  ImmutableFile readOnly(db);
  if (!readOnly.ok()) GTEST_SKIP() << "needs root for chattr +i";
  expectOneLineError(simulate(db, 2), "is read-only");
  EXPECT_TRUE(readText(db) == before);
  // Readers still work on the read-only file.
  const auto exported = runCommand(kTlab + " export " + tlab::testing::quoted(db) + " --csv " + tlab::testing::quoted((dir / "csv").string()));
  EXPECT_EQ(exported.exitCode, 0) << exported.err;
  readOnly.release();
  ASSERT_EQ(simulate(db, 2).exitCode, 0);
  expectComplete(db, 2);
}

TEST(StorageFaults, LockedDatabaseWaitsThenStopsAndResumeCompletes) {
  const auto dir = freshDir("fault_locked");
  const std::string db = (dir / "study.db").string();
  ASSERT_EQ(simulate(db, 1).exitCode, 0);
  {
    Database other(db, false);  // another process's connection, holding the write lock throughout
    other.execute("BEGIN EXCLUSIVE");
    expectOneLineError(simulate(db, 2), "is locked by another process (waited 10 s)");
    other.execute("ROLLBACK");
  }
  ASSERT_EQ(simulate(db, 2).exitCode, 0);
  expectComplete(db, 2);
}

TEST(StorageFaults, TruncatedDatabaseIsRefusedUntouchedAndRestoredCopyResumes) {
  const auto dir = freshDir("fault_truncated");
  const std::string db = (dir / "study.db").string(), backup = (dir / "backup.db").string();
  ASSERT_EQ(simulate(db, 2).exitCode, 0);
  std::filesystem::copy_file(db, backup);
  std::filesystem::resize_file(db, std::filesystem::file_size(db) / 2);
  const std::string damaged = readText(db);
  expectOneLineError(simulate(db, 3), "is damaged");
  EXPECT_TRUE(readText(db) == damaged) << "tlab wrote to a damaged database";
  std::filesystem::resize_file(db, 100);  // not even a header
  expectOneLineError(simulate(db, 3), "damaged");
  std::filesystem::copy_file(backup, db, std::filesystem::copy_options::overwrite_existing);
  ASSERT_EQ(simulate(db, 3).exitCode, 0);
  expectComplete(db, 3);
}

TEST(StorageFaults, DatabaseFromANewerTlabIsRefusedUntouched) {
  const auto dir = freshDir("fault_future");
  const std::string db = (dir / "study.db").string();
  ASSERT_EQ(simulate(db, 1).exitCode, 0);
  Database(db, false).execute("PRAGMA user_version = 99");
  const std::string before = readText(db);
  expectOneLineError(simulate(db, 2), "written by a newer tlab (schema version 99; this tlab reads up to " +
                                          std::to_string(tlab::study::latestSchemaVersion()) + ")");
  EXPECT_TRUE(readText(db) == before);
}

TEST(StorageFaults, SchemaOneDatabaseIsMigratedAndKeepsItsResponses) {
  const auto dir = freshDir("fault_migrate");
  const std::string db = (dir / "study.db").string(), current = (dir / "current.db").string();
  ASSERT_EQ(simulate(current, 1).exitCode, 0);
  const auto before = storedAnswers(current);
  {
    // What the schema-1 tlab left: its tables, holding the rows of a current run.
    Database d(db, true);
    tlab::study::migrateSchema(d, 1);
    d.execute(("ATTACH '" + current + "' AS src").c_str());
    d.execute("INSERT INTO experiments SELECT id, experiment_id, file_path, file_text, sha256, tlab_version, created_at FROM src.experiments;"
              "INSERT INTO participants SELECT * FROM src.participants; INSERT INTO assignments SELECT * FROM src.assignments;"
              "INSERT INTO sessions SELECT id, participant, mode, started_at, ended_at, end_reason FROM src.sessions;"
              "INSERT INTO trials SELECT * FROM src.trials; INSERT INTO responses SELECT id, trial, session, raw_answer, answered, correct,"
              " score, partial_credit, error, rt_seconds, onset_ns, response_ns, note, recorded_at FROM src.responses;"
              "INSERT INTO events SELECT * FROM src.events; INSERT INTO questionnaire_answers SELECT id, participant, session,"
              " questionnaire, block, item, value, recorded_at FROM src.questionnaire_answers;"
              "DETACH src");
  }
  // A reader migrates a copy in memory and leaves the old file as it was.
  const std::string oldBytes = readText(db);
  EXPECT_EQ(runCommand(kTlab + " export " + tlab::testing::quoted(db) + " --csv " + tlab::testing::quoted((dir / "csv").string())).exitCode, 0);
  EXPECT_TRUE(readText(db) == oldBytes) << "a reader changed the schema-1 file";
  ASSERT_EQ(simulate(db, 2).exitCode, 0);
  Database d(db, false);
  EXPECT_EQ(d.userVersion(), tlab::study::latestSchemaVersion());
  auto migrations = d.prepare("SELECT group_concat(version) FROM schema_migrations");
  ASSERT_TRUE(migrations.step());
  EXPECT_EQ(migrations.text(0), "2,3,4");
  auto stations = d.prepare("SELECT count(*), count(station) FROM sessions");
  ASSERT_TRUE(stations.step());
  EXPECT_EQ(stations.integer(0), 2);
  EXPECT_EQ(stations.integer(1), 1) << "only the session run after the migration knows its station";
  auto versions = d.prepare("SELECT count(*), min(version) FROM experiments");
  ASSERT_TRUE(versions.step());
  EXPECT_EQ(versions.integer(0), 1);
  EXPECT_EQ(versions.integer(1), 1);
  const auto after = storedAnswers(db);
  for (const auto& [key, answer] : before) EXPECT_EQ(after.at(key), answer);
  expectComplete(db, 2);
}

TEST(StorageFaults, MigrationsRunInOrderToTheLatestVersion) {
  const auto dir = freshDir("fault_migrations");
  Database d((dir / "m.db").string(), true);
  const auto& all = tlab::study::schemaMigrations();
  for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i].version, int(i) + 1);
  EXPECT_EQ(tlab::study::SqliteStore::kSchemaVersion, tlab::study::latestSchemaVersion());
  EXPECT_EQ(tlab::study::migrateSchema(d, 1), 1);
  EXPECT_EQ(d.userVersion(), 1);
  EXPECT_EQ(tlab::study::migrateSchema(d), int(all.size()) - 1);
  EXPECT_EQ(tlab::study::migrateSchema(d), 0);
  EXPECT_EQ(d.userVersion(), tlab::study::latestSchemaVersion());
}

TEST(StorageFaults, TwoStationsOnOneDatabaseKeepTheirSessionsApart) {
  const auto dir = freshDir("fault_two_stations");
  const std::string db = (dir / "study.db").string();
  auto station = [&](int first, const std::string& name) {
    return spawnProcess({kTlab, "simulate", studyData("crash.toml"), "--participants", "3", "--first", std::to_string(first), "--db", db,
                         "--trials", "--pace", "0.001"},
                        (dir / (name + ".out")).string(), (dir / (name + ".err")).string());
  };
  const pid_t a = station(1, "a"), b = station(4, "b");  // both create the database at once
  EXPECT_EQ(waitProcess(a), 0) << readText((dir / "a.err").string());
  EXPECT_EQ(waitProcess(b), 0) << readText((dir / "b.err").string());
  expectAcknowledgedStored(readText((dir / "a.out").string()), db);
  expectAcknowledgedStored(readText((dir / "b.out").string()), db);
  expectComplete(db, 6);
  Database d(db, false);
  // Six slots 0..5, one per participant, and every session's responses belong to its participant.
  auto slots = d.prepare("SELECT count(DISTINCT slot), min(slot), max(slot) FROM assignments WHERE status = 'finished'");
  ASSERT_TRUE(slots.step());
  EXPECT_EQ(slots.integer(0), 6);
  EXPECT_EQ(slots.integer(1), 0);
  EXPECT_EQ(slots.integer(2), 5);
  auto mixed = d.prepare(
      "SELECT count(*) FROM responses r JOIN sessions s ON s.id = r.session JOIN trials t ON t.id = r.trial "
      "WHERE t.participant != s.participant");
  ASSERT_TRUE(mixed.step());
  EXPECT_EQ(mixed.integer(0), 0);
  auto stations = d.prepare("SELECT count(DISTINCT station) FROM sessions");
  ASSERT_TRUE(stations.step());
  EXPECT_EQ(stations.integer(0), 2);
  // The two stations really overlapped in time (otherwise this test proves nothing).
  auto overlap = d.prepare(
      "SELECT count(*) FROM sessions s1 JOIN sessions s2 ON s1.station < s2.station "
      "WHERE s1.started_at < s2.ended_at AND s2.started_at < s1.ended_at");
  ASSERT_TRUE(overlap.step());
  EXPECT_GT(overlap.integer(0), 0);
}
