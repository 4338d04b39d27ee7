// End to end through `tlab` on a PostgreSQL URL (this test process's throw-away cluster): simulate,
// export, analyze, report, design and drop take the URL; the exported CSV files equal those of the
// same simulation into an SQLite file (columns of wall-clock time and the station left out); the
// readers leave every table as it was; four stations write one new database at once; a station
// killed inside a response transaction loses only that unacknowledged answer; an unreachable
// server or a wrong user is one line, exit 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "tests/study/store_backends.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;

namespace {

const std::string kTlab = TLAB_EXE;

// Columns whose values legitimately differ between two runs: wall-clock times and host:pid.
const std::set<std::string> kRunDependent = {"recorded_at", "started_at", "ended_at", "assigned_at", "finished_at", "station"};

std::vector<std::vector<std::string>> withoutRunDependentColumns(const std::string& csvPath) {
  auto rows = parseCsv(readText(csvPath));
  if (rows.empty()) return rows;
  std::vector<bool> keep;
  for (const auto& name : rows[0]) keep.push_back(!kRunDependent.count(name));
  for (auto& row : rows) {
    std::vector<std::string> kept;
    for (std::size_t c = 0; c < row.size(); ++c)
      if (c >= keep.size() || keep[c]) kept.push_back(row[c]);
    row = kept;
  }
  return rows;
}

// A checksum of every row of every study table.
std::string tableChecksum(const std::string& url) {
  std::string sql = "SELECT md5(string_agg(x, ',' ORDER BY x)) FROM (";
  const char* tables[] = {"schema_migrations", "experiments", "participants", "assignments", "sessions", "trials",
                          "responses", "events", "questionnaire_answers", "consent", "participant_info"};
  for (std::size_t i = 0; i < std::size(tables); ++i)
    sql += std::string(i ? " UNION ALL " : "") + "SELECT '" + tables[i] + "' || md5(coalesce(string_agg(t::text, '|' ORDER BY t::text), '')) AS x FROM " +
           tables[i] + " t";
  return storeBackend("postgres").peek(url, sql + ") all_tables");
}

// `tlab simulate` as a station in `dir` (a URL's stimuli go to the working directory), acknowledging each answer.
pid_t station(const std::filesystem::path& dir, const std::string& url, int first, int participants, const std::string& name,
              const std::vector<std::string>& env = {}, bool resume = false) {
  std::vector<std::string> args = {TLAB_EXE, "simulate", studyData("crash.toml"), "--participants", std::to_string(participants),
                                   "--first", std::to_string(first), "--db", url, "--trials"};
  if (resume) args.push_back("--resume");
  return spawnProcess({"/bin/sh", "-c", "cd " + tlab::testing::quoted(dir.string()) + " && exec " + commandLine(args)},
                      (dir / (name + ".out")).string(), (dir / (name + ".err")).string(), env);
}

void expectOneLineError(const CommandResult& r, const std::string& part) {
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
}

}  // namespace

TEST(PostgresCli, SimulateExportAnalyzeReportAndDropOnAUrlGiveWhatSqliteGives) {
  const std::string url = sharedPostgresCluster().createDatabase("sim");
  const auto dir = freshDir("pg_cli");
  const std::string in = "cd " + tlab::testing::quoted(dir.string()) + " && ";
  // Both in the same folder: sim.db and the database "sim" share the stimulus folder sim-stimuli.
  const auto file = runCommand(in + kTlab + " simulate " + studyData("tiny.toml") + " --participants 4 --db sim.db");
  ASSERT_EQ(file.exitCode, 0) << file.err;
  const auto server = runCommand(in + kTlab + " simulate " + studyData("tiny.toml") + " --participants 4 --db " + tlab::testing::quoted(url));
  ASSERT_EQ(server.exitCode, 0) << server.err;
  EXPECT_NE(server.out.find("simulated 4 participants"), std::string::npos) << server.out;

  const std::string before = tableChecksum(url);
  ASSERT_EQ(runCommand(in + kTlab + " export sim.db --csv csv-file").exitCode, 0);
  const auto exported = runCommand(in + kTlab + " export " + tlab::testing::quoted(url) + " --csv csv-server");
  ASSERT_EQ(exported.exitCode, 0) << exported.err;
  for (const char* name : {"trials.csv", "sessions.csv", "questionnaires.csv", "participants.csv", "events.csv", "participant_info.csv",
                           "consent.csv"}) {
    const auto a = withoutRunDependentColumns((dir / "csv-file" / name).string());
    const auto b = withoutRunDependentColumns((dir / "csv-server" / name).string());
    EXPECT_EQ(a.size(), b.size()) << name;
    EXPECT_TRUE(a == b) << name << " differs";
  }
  const auto analyzedFile = runCommand(in + kTlab + " analyze sim.db");
  const auto analyzed = runCommand(in + kTlab + " analyze " + tlab::testing::quoted(url));
  ASSERT_EQ(analyzed.exitCode, 0) << analyzed.err;
  EXPECT_EQ(analyzed.out, analyzedFile.out);
  const auto report = runCommand(in + kTlab + " report " + tlab::testing::quoted(url) + " -o report.html");
  ASSERT_EQ(report.exitCode, 0) << report.err;
  ASSERT_EQ(runCommand(in + kTlab + " design " + studyData("tiny.toml") + " --db " + tlab::testing::quoted(url)).exitCode, 0);
  EXPECT_EQ(tableChecksum(url), before) << "a reader changed the database";

  const auto drop = runCommand(in + kTlab + " drop " + tlab::testing::quoted(url) + " --participant sim-003 --reason test");
  ASSERT_EQ(drop.exitCode, 0) << drop.err;
  const auto json = nlohmann::json::parse(runCommand(in + kTlab + " analyze " + tlab::testing::quoted(url) + " --json").out);
  EXPECT_EQ(json["analyses"][0]["subjects"], 3);  // the dropped participant is left out
}

TEST(PostgresCli, AnUnreachableServerOrAWrongUserIsOneLine) {
  const auto dir = freshDir("pg_cli_errors");
  const std::string nowhere = "postgresql://ann:s3cret@/study?host=/nonexistent-tlab-socket-dir&port=5999";
  const auto unreachable = runCommand(kTlab + " export " + tlab::testing::quoted(nowhere) + " --csv " + tlab::testing::quoted((dir / "csv").string()));
  expectOneLineError(unreachable, "cannot connect to PostgreSQL at postgresql://ann@/study?host=/nonexistent-tlab-socket-dir&port=5999: ");
  EXPECT_EQ(unreachable.err.find("s3cret"), std::string::npos) << unreachable.err;
  std::string wrongUser = sharedPostgresCluster().url("postgres");
  wrongUser.replace(wrongUser.find("user=tlab"), 9, "user=mallory");
  expectOneLineError(runCommand(kTlab + " simulate " + studyData("tiny.toml") + " --participants 1 --db " + tlab::testing::quoted(wrongUser)),
                     "role \"mallory\" does not exist");
}

TEST(PostgresCli, FourStationsOnOneNewDatabaseStoreEveryAcknowledgedAnswerOnce) {
  const std::string url = sharedPostgresCluster().createDatabase("stations");
  const auto dir = freshDir("pg_cli_stations");
  constexpr int kEach = 10, kTrials = 12;  // crash.toml: 12 questions per participant
  std::vector<pid_t> stations;
  for (int s = 0; s < 4; ++s) stations.push_back(station(dir, url, 1 + kEach * s, kEach, "s" + std::to_string(s)));
  std::set<std::pair<std::string, int>> acknowledged;
  for (int s = 0; s < 4; ++s) {
    EXPECT_EQ(waitProcess(stations[std::size_t(s)]), 0) << readText((dir / ("s" + std::to_string(s) + ".err")).string());
    for (const auto& a : parseAcks(readText((dir / ("s" + std::to_string(s) + ".out")).string()))) acknowledged.insert({a.participant, a.sequence});
  }
  auto& db = storeBackend("postgres");
  EXPECT_EQ(acknowledged.size(), std::size_t(4 * kEach * kTrials));
  EXPECT_EQ(db.peek(url, "SELECT count(*) FROM responses"), std::to_string(4 * kEach * kTrials));
  EXPECT_EQ(db.peek(url, "SELECT count(DISTINCT slot) || ' ' || max(slot) FROM assignments"), std::to_string(4 * kEach) + " " + std::to_string(4 * kEach - 1));
  EXPECT_EQ(db.peek(url, "SELECT count(*) FROM experiments"), "1");
  EXPECT_EQ(db.peek(url, "SELECT count(*) FROM participants WHERE status = 'finished'"), std::to_string(4 * kEach));
}

TEST(PostgresCli, AStationKilledInsideAResponseLosesOnlyThatUnacknowledgedAnswer) {
  const std::string url = sharedPostgresCluster().createDatabase("killed");
  const auto dir = freshDir("pg_cli_killed");
  // Stopped inside the 5th response transaction, after its inserts, before COMMIT; then killed.
  const pid_t a = station(dir, url, 1, 1, "a", {"TLAB_STOP_AT=commit:5"});
  int status = 0;
  ::waitpid(a, &status, WUNTRACED);
  ASSERT_TRUE(WIFSTOPPED(status)) << readText((dir / "a.err").string());
  ::kill(a, SIGKILL);
  waitProcess(a);
  const auto acks = parseAcks(readText((dir / "a.out").string()));
  EXPECT_EQ(acks.size(), 4u);
  auto& db = storeBackend("postgres");
  // The server notices the dead connection and rolls its transaction back.
  std::string stored;
  for (int i = 0; i < 100 && (stored = db.peek(url, "SELECT count(*) FROM responses")) != "4"; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(stored, "4");
  const pid_t b = station(dir, url, 1, 1, "b", {}, true);  // --resume: the dead station's session is resumed
  EXPECT_EQ(waitProcess(b), 0) << readText((dir / "b.err").string());
  EXPECT_EQ(db.peek(url, "SELECT count(*) FROM responses"), "12");
  EXPECT_EQ(db.peek(url, "SELECT count(*) FROM sessions WHERE end_reason = 'interrupted' AND resumed_by IS NOT NULL"), "1");
}
