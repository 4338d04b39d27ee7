// The README's "Running a study online" steps, followed as a researcher would: the tlab commands
// of its tested block run as written (the database URL of a throw-away PostgreSQL cluster in place
// of step 1, and a free loopback port in place of 0.0.0.0:8080), a pilot participant takes the
// Prolific link serve printed, the admin link shows them, and export, analyze and report read
// the database.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "tests/study/serve_test_client.hpp"
#include "tests/study/served_study.hpp"
#include "tests/support/postgres_cluster.hpp"

namespace tlab::testing {
namespace {

using nlohmann::json;

// The `tlab ...` lines of the README block marked "NAME: tested".
std::vector<std::string> readmeCommands(const std::string& name = "online-steps") {
  const std::string readme = readText(std::string(TLAB_SOURCE_DIR) + "/README.md");
  const auto marker = readme.find("<!-- " + name + ": tested -->");
  if (marker == std::string::npos) throw std::runtime_error("README.md: no " + name + " block");
  const auto begin = readme.find("```sh\n", marker), end = readme.find("```\n", begin + 6);
  std::istringstream block(readme.substr(begin + 6, end - begin - 6));
  std::vector<std::string> commands;
  for (std::string line; std::getline(block, line);)
    if (line.rfind("tlab ", 0) == 0) commands.push_back(line);
  return commands;
}

std::string substituted(std::string command, const std::string& url, const std::filesystem::path& dir) {
  command = std::regex_replace(command, std::regex("^tlab "), std::string(TLAB_EXE) + " ");
  command = std::regex_replace(command, std::regex("\"\\$DB\""), quoted(url));
  command = std::regex_replace(command, std::regex("examples/"), std::string(TLAB_SOURCE_DIR) + "/examples/");
  return std::regex_replace(command, std::regex(" results"), " " + (dir / "results").string());
}

TEST(ServeReadme, TheOnlineStepsWorkAsWritten) {
  const auto commands = readmeCommands();
  ASSERT_EQ(commands.size(), 5u);
  EXPECT_EQ(commands[1], "tlab serve examples/online.toml --db \"$DB\" --listen 0.0.0.0:8080");
  const auto dir = freshDir("serve_readme");
  const std::string url = sharedPostgresCluster().createDatabase("online_demo");

  const auto design = runCommand(substituted(commands[0], url, dir));
  ASSERT_EQ(design.exitCode, 0) << design.err;
  ServedStudy server(example("online.toml"), url, dir);  // step 2, on a free loopback port
  std::smatch link;
  const std::string printed = server.stdoutText();
  // --quiet hides the bar, not the phases: a line before the minutes of preparation.
  EXPECT_NE(printed.find("serve: preparing every stimulus of"), std::string::npos) << printed;
  ASSERT_TRUE(std::regex_search(printed, link, std::regex("for Prolific: +http://127\\.0\\.0\\.1:[0-9]+/s/([^?]+)\\?(\\S+)"))) << printed;
  std::string query = link[2];  // step 3: a pilot takes the Prolific link
  query = std::regex_replace(query, std::regex("\\{\\{%PROLIFIC_PID%\\}\\}"), "pilot-1");
  query = std::regex_replace(query, std::regex("\\{\\{%(STUDY_ID|SESSION_ID)%\\}\\}"), "readme");
  PageClient page(server.port());
  const auto [status, token] = page.arrive(link[1], query);
  ASSERT_EQ(status, 303);
  const Walk w = walk(page, token, page.api(token, "display", display()).body);  // the size calibration comes after consent
  ASSERT_EQ(w.screens.back()["kind"], "end") << w.screens.back().dump();
  EXPECT_EQ(w.screens.back()["completion_code"], "TLABDEMO");
  std::smatch admin;  // step 4
  ASSERT_TRUE(std::regex_search(printed, admin, std::regex("admin: http://127\\.0\\.0\\.1:[0-9]+(/admin\\?token=[0-9a-f]+)")));
  const auto monitor = page.raw(admin[1]);
  EXPECT_EQ(monitor->status, 200);
  EXPECT_NE(monitor->body.find("pilot-1"), std::string::npos);
  server.stop(SIGTERM);

  for (std::size_t i = 2; i < commands.size(); ++i) {  // step 5
    const auto r = runCommand(substituted(commands[i], url, dir));
    EXPECT_EQ(r.exitCode, 0) << commands[i] << ": " << r.err;
  }
  const auto trials = parseCsv(readText((dir / "results" / "trials.csv").string()));
  EXPECT_EQ(trials.size(), 1u + w.answered);
  EXPECT_TRUE(std::filesystem::exists(dir / "results" / "report.html"));
  std::filesystem::remove_all(dir);
}

// "### Live views online": Elmqvist's whole study served, its orbit (T1, T2) and walk (T3, T4)
// trials rendered live, walked by the load tester's simulated participant as the README shows.
TEST(ServeReadme, ElmqvistRunsWholeOnlineWithLiveViewsAsWritten) {
  const auto commands = readmeCommands("live-steps");
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_EQ(commands[0], "tlab serve examples/elmqvist.toml --db elmqvist.db --listen 0.0.0.0:8080");
  const auto dir = freshDir("serve_readme_live");
  const std::string db = (dir / "elmqvist.db").string();
  ServedStudy server(example("elmqvist.toml"), db, dir);  // the first line, on a free loopback port
  const std::string load = std::regex_replace(substituted(commands[1], db, dir), std::regex("http://127\\.0\\.0\\.1:8080/s/elmqvist2008"), server.link());
  const auto r = runCommand(load);
  EXPECT_EQ(server.stop(SIGTERM), 0);
  ASSERT_EQ(r.exitCode, 0) << load << "\n" << r.out << r.err;
  EXPECT_NE(r.out.find("participants: 1 finished, 0 failed"), std::string::npos) << r.out;
  EXPECT_EQ(queryCount(db, "SELECT COUNT(*) FROM responses WHERE answered = 1"), queryCount(db, "SELECT COUNT(*) FROM trials"));
  for (const char* task : {"T1", "T2", "T3", "T4"})  // every task explored live: frames logged with its trials
    EXPECT_GT(queryCount(db, std::string("SELECT COUNT(*) FROM events e JOIN trials t ON t.id = e.trial WHERE e.kind = 'frame' AND t.task_id = '") + task + "'"), 0)
        << task;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tlab::testing
