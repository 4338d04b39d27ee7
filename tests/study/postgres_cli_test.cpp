// End to end through `tlab` on a PostgreSQL URL (this test process's throw-away cluster): simulate,
// export, analyze, report, design and drop take the URL; the exported CSV files equal those of the
// same simulation into an SQLite file (columns of wall-clock time and the station left out); the
// readers leave every table as it was; an unreachable server or a wrong user is one line, exit 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

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
