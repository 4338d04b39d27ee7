// tlab serve on a PostgreSQL store (a throw-away cluster of this test process): the same session
// as on SQLite, and a database server that goes away in the middle of a study — the answer on its
// way is refused with a retry message in the page, nothing acknowledged is lost, and after the
// server is back the participant continues where they stopped.
#include <gtest/gtest.h>

#include "tests/study/serve_test_client.hpp"
#include "tests/study/served_study.hpp"
#include "tests/support/postgres_cluster.hpp"

namespace tlab::testing {
namespace {

using nlohmann::json;

std::string arriveAs(PageClient& page, const std::string& pid) {
  const auto [status, token] = page.arrive("serve-tiny", "PROLIFIC_PID=" + pid);
  EXPECT_EQ(status, 303);
  return token;
}

TEST(ServePostgres, ASessionIsStoredAsOnSqliteAndALostDatabaseLosesNothingAcknowledged) {
  const auto dir = freshDir("serve_postgres");
  PostgresCluster& cluster = sharedPostgresCluster();
  const std::string url = cluster.createDatabase("served");
  ServedStudy server(studyData("serve_tiny.toml"), url, dir);
  EXPECT_NE(server.stdoutText().find("store: postgresql:///served"), std::string::npos) << server.stdoutText();
  PageClient page(server.port());
  const std::string token = arriveAs(page, "p1");
  const Walk before = walk(page, token, page.api(token, "display", display()).body, 3);
  ASSERT_EQ(before.screens.back()["kind"], "trial");

  cluster.stop();  // the database server goes away mid-study
  const json trial = before.screens.back();
  EXPECT_EQ(page.api(token, "reply", {{"seq", trial["seq"]}, {"type", "onset"}, {"painted_ms", 1}}).status, 200);
  const Reply lost = page.api(token, "reply", {{"seq", trial["seq"]}, {"type", "answer"}, {"answer", 2}, {"rt_ms", 640}});
  // The onset or the answer meets the lost database: either way the page is told to try again.
  const json shown = lost.status == 409 ? lost.body["screen"] : lost.body;
  EXPECT_EQ(shown["kind"], "error") << lost.body.dump();
  EXPECT_EQ(shown["retry"], true);
  EXPECT_EQ(lost.body.dump().find("postgresql"), std::string::npos) << "the page is not told the database's address";
  EXPECT_NE(server.stderrText().find("was not stored"), std::string::npos) << server.stderrText();
  const auto arrival = page.arrive("serve-tiny", "PROLIFIC_PID=p2");
  EXPECT_EQ(arrival.first, 500) << "a newcomer gets an honest page while the database is away";

  cluster.start();  // back: the page's "try again" reports the display again and the flow resumes
  const Walk after = walk(page, token, page.api(token, "display", display()).body);
  EXPECT_EQ(after.screens.back()["kind"], "end") << after.screens.back().dump() << server.stderrText();
  EXPECT_EQ(before.answered + after.answered, 10);
  server.stop(SIGTERM);

  const auto trials = exportedTable(url, dir, "trials");
  ASSERT_EQ(trials.size(), 11u);
  for (std::size_t i = 1; i < trials.size(); ++i) EXPECT_EQ(trials[i][column(trials, "responded")], "1") << "trial " << i;
  const auto sessions = exportedTable(url, dir, "sessions");
  EXPECT_EQ(sessions.size(), 3u) << "the session the lost database stopped, and the one that resumed it";
  EXPECT_EQ(sessions.back()[column(sessions, "status")], "finished");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tlab::testing
