// The study log as a semester of data collection needs it, end to end through `tlab`: stations
// sharing one new database, one participant claimed by two stations, a start that fails before
// anything is written, versions of an experiment file, and readers that never change a file.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "study/store/sqlite_database.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;
using tlab::study::Database;

namespace {

const std::string kTlab = TLAB_EXE;
constexpr int kTrialsPerParticipant = 12;  // crash.toml: 4 blocks × 3 questions

std::vector<std::string> stationArgs(const std::string& db, int first, int participants, const std::string& experiment = "crash.toml") {
  return {kTlab, "simulate", studyData(experiment), "--participants", std::to_string(participants), "--first", std::to_string(first),
          "--db", db, "--trials"};
}

void expectOneLineError(const CommandResult& r, const std::string& part) {
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_EQ(r.err.rfind("tlab: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
}

// Every file of `dir` with its bytes.
std::map<std::string, std::string> snapshot(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.is_regular_file()) files[e.path().filename().string()] = readText(e.path().string());
  return files;
}

std::string withText(const std::string& path, const std::string& from, const std::string& to) {
  std::string text = readText(path);
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("no '" + from + "' in " + path);
  return text.replace(at, from.size(), to);
}

void writeText(const std::filesystem::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

}  // namespace

TEST(StudyLog, FourStationsOnOneNewDatabase) {
  const auto dir = freshDir("log_four_stations");
  const std::string db = (dir / "study.db").string();
  std::vector<pid_t> stations;
  for (int s = 0; s < 4; ++s)  // all four create the database at once
    stations.push_back(spawnProcess(stationArgs(db, 1 + 25 * s, 25), (dir / ("s" + std::to_string(s) + ".out")).string(),
                                    (dir / ("s" + std::to_string(s) + ".err")).string()));
  std::set<std::pair<std::string, int>> acknowledged;
  for (int s = 0; s < 4; ++s) {
    EXPECT_EQ(waitProcess(stations[std::size_t(s)]), 0) << readText((dir / ("s" + std::to_string(s) + ".err")).string());
    for (const auto& a : parseAcks(readText((dir / ("s" + std::to_string(s) + ".out")).string())))
      acknowledged.insert({a.participant, a.sequence});
  }
  EXPECT_EQ(acknowledged.size(), std::size_t(100 * kTrialsPerParticipant));
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM responses"), 100 * kTrialsPerParticipant);
  EXPECT_EQ(queryCount(db, "SELECT count(DISTINCT slot) FROM assignments"), 100);
  EXPECT_EQ(queryCount(db, "SELECT max(slot) FROM assignments"), 99);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM experiments"), 1);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM participants WHERE status = 'finished'"), 100);
  Database d(db, false);
  for (const auto& [participant, sequence] : acknowledged) {
    auto s = d.prepare("SELECT count(*) FROM responses r JOIN trials t ON t.id = r.trial JOIN participants p ON p.id = t.participant "
                       "WHERE p.participant = ?1 AND t.sequence = ?2");
    s.bind(1, participant).bind(2, sequence);
    ASSERT_TRUE(s.step());
    ASSERT_EQ(s.integer(0), 1) << participant << " #" << sequence;
  }
}

TEST(StudyLog, AParticipantRunningAtOneStationIsRefusedAtAnother) {
  const auto dir = freshDir("log_same_participant");
  const std::string db = (dir / "study.db").string();
  ASSERT_EQ(runCommand(kTlab + " simulate " + studyData("crash.toml") + " --participants 1 --db " + db + " --trials").exitCode, 0);
  auto resume = stationArgs(db, 2, 1);
  resume.push_back("--resume");
  // Station A holds sim-002's session: stopped right after it started (it is alive, not finished).
  const pid_t a = spawnProcess(resume, (dir / "a.out").string(), (dir / "a.err").string(), {"TLAB_STOP_AT=session:1"});
  int status = 0;
  ::waitpid(a, &status, WUNTRACED);
  ASSERT_TRUE(WIFSTOPPED(status)) << readText((dir / "a.err").string());
  const auto before = queryCount(db, "SELECT count(*) FROM responses");
  expectOneLineError(runCommand(commandLine(resume)), "participant 'sim-002' is in session ");
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM responses"), before);
  // Station A goes on and finishes; the participant is then finished for everyone.
  ::kill(a, SIGCONT);
  EXPECT_EQ(waitProcess(a), 0) << readText((dir / "a.err").string());
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM responses"), 2 * kTrialsPerParticipant);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM sessions WHERE ended_at IS NULL"), 0);
}

TEST(StudyLog, DesignCatchesWhatStimuliWouldFailOnAndNothingIsWritten) {
  const auto dir = freshDir("log_design_checks");
  const std::string file = studyData("crash.toml");
  const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
      {"builtin:open-cylinders", "builtin:open-cylinder", "crash.toml:23: factors[2].levels[1].scene: unknown built-in scene 'open-cylinder'"},
      {"builtin:nested-spheres?n=2", "builtin:nested-spheres?n=0", "factors[2].levels[2].scene: built-in scene 'nested-spheres' parameter 'n'"},
      {"alpha=0.2", "alfa=0.2", "crash.toml:16: factors[1].levels[1].settings: style 'constant' has no parameter 'alfa'"},
      {"alpha=0.6", "alpha=2", "factors[1].levels[2].settings: style 'constant' parameter 'alpha'"},
      {"style = \"constant\"", "style = \"smartt\"", "crash.toml:11: stimulus.style: unknown style 'smartt'"},
      {"builtin:open-cylinders", "missing-model.gltf", "factors[2].levels[1].scene: "},
  };
  for (const auto& [from, to, message] : cases) {
    const auto bad = dir / "crash.toml";
    writeText(bad, withText(file, from, to));
    expectOneLineError(runCommand(kTlab + " design " + quoted(bad.string())), message);
    const std::string db = (dir / "study.db").string();
    expectOneLineError(runCommand(kTlab + " simulate " + quoted(bad.string()) + " --participants 1 --db " + quoted(db)), message);
    EXPECT_FALSE(std::filesystem::exists(db)) << to;
    EXPECT_FALSE(std::filesystem::exists(dir / "study-stimuli")) << to;
  }
}

TEST(StudyLog, AStartKilledWhilePreparingStimuliLeavesNoRows) {
  const auto dir = freshDir("log_failed_start");
  const std::string db = (dir / "study.db").string();
  const pid_t p = spawnProcess(stationArgs(db, 1, 1), (dir / "p.out").string(), (dir / "p.err").string(), {"TLAB_STOP_AT=prepare:5"});
  int status = 0;
  ::waitpid(p, &status, WUNTRACED);
  ASSERT_TRUE(WIFSTOPPED(status)) << readText((dir / "p.err").string());
  ::kill(p, SIGKILL);
  waitProcess(p);
  for (const char* table : {"experiments", "participants", "assignments", "sessions", "trials"})
    EXPECT_EQ(queryCount(db, std::string("SELECT count(*) FROM ") + table), 0) << table;
  // Fixed and started again, the study runs as if nothing had happened.
  ASSERT_EQ(runCommand(kTlab + " simulate " + studyData("crash.toml") + " --participants 1 --db " + db).exitCode, 0);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM responses"), kTrialsPerParticipant);
}

TEST(StudyLog, EditedFilesAreVersionsAndDesignChangesAreNotPooledUnlessAsked) {
  const auto dir = freshDir("log_versions");
  const std::string db = (dir / "study.db").string(), file = studyData("tiny.toml");
  auto simulate = [&](const std::string& path, int first) {
    return runCommand(kTlab + " simulate " + quoted(path) + " --participants 2 --first " + std::to_string(first) + " --db " + quoted(db));
  };
  ASSERT_EQ(simulate(file, 1).exitCode, 0);
  const auto retitled = dir / "retitled.toml";  // a text-only edit: pooled without asking
  writeText(retitled, readText(file) + "\n# wording of the instructions improved while piloting\n");
  ASSERT_EQ(simulate(retitled.string(), 3).exitCode, 0);
  auto analyzed = runCommand(kTlab + " analyze " + quoted(db));
  ASSERT_EQ(analyzed.exitCode, 0) << analyzed.err;
  EXPECT_NE(analyzed.out.find("data from version 1 ("), std::string::npos) << analyzed.out;
  EXPECT_NE(analyzed.out.find("; version 2 ("), std::string::npos) << analyzed.out;
  const auto redesigned = dir / "redesigned.toml";  // another design: refused unless pooled on purpose
  writeText(redesigned, withText(file, "seed = ", "seed = 1"));
  ASSERT_EQ(simulate(redesigned.string(), 5).exitCode, 0);
  expectOneLineError(runCommand(kTlab + " analyze " + quoted(db)), "come from versions whose designs differ");
  expectOneLineError(runCommand(kTlab + " export " + quoted(db) + " --csv " + quoted((dir / "csv").string())), "--pool-versions");
  ASSERT_EQ(runCommand(kTlab + " analyze " + quoted(db) + " --pool-versions").exitCode, 0);
  const auto exported = runCommand(kTlab + " export " + quoted(db) + " --csv " + quoted((dir / "csv").string()) + " --pool-versions");
  ASSERT_EQ(exported.exitCode, 0) << exported.err;
  const auto sessions = parseCsv(readText((dir / "csv" / "sessions.csv").string()));
  ASSERT_EQ(sessions.size(), 1u + 6);
  std::set<std::string> versions;
  for (std::size_t i = 1; i < sessions.size(); ++i) versions.insert(sessions[i][3]);
  EXPECT_EQ(versions, (std::set<std::string>{"1", "2", "3"}));
}

TEST(StudyLog, ReadersNeverChangeAFile) {
  const auto dir = freshDir("log_readers");
  const std::string db = (dir / "study.db").string();
  ASSERT_EQ(runCommand(kTlab + " simulate " + studyData("tiny.toml") + " --participants 2 --db " + quoted(db)).exitCode, 0);
  const auto out = freshDir("log_readers_out");
  auto readAll = [&](const std::string& path) {
    std::vector<CommandResult> results;
    results.push_back(runCommand(kTlab + " analyze " + quoted(path)));
    results.push_back(runCommand(kTlab + " export " + quoted(path) + " --csv " + quoted((out / "csv").string())));
    results.push_back(runCommand(kTlab + " report " + quoted(path) + " -o " + quoted((out / "r.html").string())));
    results.push_back(runCommand(kTlab + " design " + studyData("tiny.toml") + " --db " + quoted(path)));
    return results;
  };
  // A cleanly closed study database: the folder stays byte for byte as it was (no -wal/-shm files).
  auto before = snapshot(dir);
  for (const auto& r : readAll(db)) EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(snapshot(dir), before);
  // Another program's SQLite file: refused, untouched (it was switched to WAL before).
  const std::string foreign = (dir / "other.db").string();
  { Database(foreign, true).execute("CREATE TABLE measurements (x); INSERT INTO measurements VALUES (1)"); }
  before = snapshot(dir);
  for (const auto& r : readAll(foreign)) expectOneLineError(r, "not a tlab study database (it has other tables: measurements)");
  expectOneLineError(runCommand(kTlab + " simulate " + studyData("tiny.toml") + " --db " + quoted(foreign)), "not a tlab study database");
  EXPECT_EQ(snapshot(dir), before);
  // A text file is not an SQLite database (not "damaged").
  writeText(dir / "notes.db", "participant notes, not a database\n");
  for (const auto& r : readAll((dir / "notes.db").string())) expectOneLineError(r, "not an SQLite database");
  // An archived study on read-only media: the folder and the file immutable (chattr +i, as root).
  if (runCommand("chattr +i " + quoted(db) + " " + quoted(dir.string()) + " 2>&1").exitCode != 0) GTEST_SKIP() << "needs root for chattr +i";
  before = snapshot(dir);
  const auto results = readAll(db);
  runCommand("chattr -i " + quoted(dir.string()) + " " + quoted(db));
  for (const auto& r : results) EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(snapshot(dir), before);
}

TEST(StudyLog, ExportSaysHowEverySessionEndedAndKeepsSeedsExact) {
  const auto dir = freshDir("log_session_status");
  const std::string db = (dir / "study.db").string();
  auto args = stationArgs(db, 1, 2);
  args.push_back("--resume");
  const pid_t p = spawnProcess(args, (dir / "p.out").string(), (dir / "p.err").string(), {"TLAB_STOP_AT=onset:4"});
  int status = 0;
  ::waitpid(p, &status, WUNTRACED);
  ASSERT_TRUE(WIFSTOPPED(status));
  ::kill(p, SIGKILL);
  waitProcess(p);
  ASSERT_EQ(runCommand(commandLine(args)).exitCode, 0);
  ASSERT_EQ(runCommand(kTlab + " export " + quoted(db) + " --csv " + quoted((dir / "csv").string())).exitCode, 0);
  const auto sessions = parseCsv(readText((dir / "csv" / "sessions.csv").string()));
  ASSERT_EQ(sessions.size(), 1u + 3);
  EXPECT_EQ(sessions[0][8], "status");
  EXPECT_EQ(sessions[1][8], "interrupted, resumed by session 2");
  EXPECT_EQ(sessions[2][8], "finished");
  EXPECT_EQ(sessions[1][11], "4");  // four stimuli were shown before the kill, three answered
  EXPECT_EQ(sessions[1][10], "3");
  const auto trials = parseCsv(readText((dir / "csv" / "trials.csv").string()));
  const auto& header = trials[0];
  const auto column = [&](const std::string& name) { return std::size_t(std::find(header.begin(), header.end(), name) - header.begin()); };
  ASSERT_LT(column("showings"), header.size());
  EXPECT_EQ(trials[4][column("showings")], "2");  // the fourth stimulus was shown again after the kill
  EXPECT_EQ(trials[1][column("showings")], "1");
  Database d(db, false);
  auto seed = d.prepare("SELECT probe_seed FROM trials t JOIN participants p ON p.id = t.participant WHERE p.participant = 'sim-001' "
                        "ORDER BY sequence LIMIT 1");
  ASSERT_TRUE(seed.step());
  EXPECT_EQ(trials[1][column("probe_seed")], "seed:" + std::to_string(std::uint64_t(seed.integer(0))));
}

TEST(StudyLog, ErrorLinesSayWhatToDo) {
  const auto dir = freshDir("log_error_lines");
  const std::string db = (dir / "study.db").string();
  // tlab run has no --window to leave out: without a display it names Xvfb and tlab simulate.
  const auto run = runCommand("env -u DISPLAY -u WAYLAND_DISPLAY " + kTlab + " run " + studyData("tiny.toml") + " --participant P01 --db " +
                              quoted(db));
  expectOneLineError(run, "tlab simulate");
  EXPECT_NE(run.err.find("xvfb-run"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("render headless"), std::string::npos) << run.err;
  // An export folder that cannot be made: one plain line naming it.
  ASSERT_EQ(runCommand(kTlab + " simulate " + studyData("tiny.toml") + " --participants 1 --db " + quoted(db)).exitCode, 0);
  const auto blocked = dir / "not-a-folder";
  writeText(blocked, "a file where the export folder should go\n");
  const auto exported = runCommand(kTlab + " export " + quoted(db) + " --csv " + quoted((blocked / "csv").string()));
  expectOneLineError(exported, (blocked / "csv").string() + ": cannot create the export folder");
  EXPECT_EQ(exported.err.find("filesystem error"), std::string::npos) << exported.err;
}

TEST(StudyLog, AnUnreplayedLogOnReadOnlyMediaIsNamed) {
  const auto dir = freshDir("log_wal_read_only");
  const auto source = dir / "source", archive = dir / "archive";
  std::filesystem::create_directories(source);
  std::filesystem::create_directories(archive);
  const std::string db = (source / "study.db").string();
  ASSERT_EQ(runCommand(kTlab + " simulate " + studyData("tiny.toml") + " --participants 1 --db " + quoted(db)).exitCode, 0);
  {
    // A station still writing: its last changes are only in the write-ahead log when the files are copied.
    Database writer(db, false);
    writer.execute("PRAGMA wal_autocheckpoint=0; INSERT INTO events (session, trial, t_ns, kind, detail) VALUES (1, NULL, 0, 'note', 'late')");
    std::filesystem::copy_file(db, archive / "study.db");
    std::filesystem::copy_file(db + "-wal", archive / "study.db-wal");
  }
  const std::string copy = (archive / "study.db").string();
  if (runCommand("chattr +i " + quoted(copy) + " " + quoted(copy + "-wal") + " " + quoted(archive.string()) + " 2>&1").exitCode != 0)
    GTEST_SKIP() << "needs root for chattr +i";
  const auto r = runCommand(kTlab + " export " + quoted(copy) + " --csv " + quoted((dir / "csv").string()));
  runCommand("chattr -i " + quoted(archive.string()) + " " + quoted(copy) + " " + quoted(copy + "-wal"));
  expectOneLineError(r, "holds changes that must be replayed, and the folder is read-only: copy");
}
