// The admin page of `tlab serve` lists, per participant, the trials whose live frames were logged
// with the `tlab replay` command of each (the admin token required, as for the whole page): a
// participant answers a trial of the tiny served study, a frame event is stored for it as a front
// end stores one, and the status and the page show its replay.
#include <gtest/gtest.h>

#include "study/run/frame_log.hpp"
#include "study/store/sqlite_database.hpp"
#include "tests/study/serve_test_client.hpp"
#include "tests/study/served_study.hpp"
#include "tests/study/study_test_support.hpp"

namespace tlab::testing {
namespace {

// A frame event for the participant's first trial in their session, as the window stores one.
void storeFrame(const std::string& db, const std::string& participant) {
  study::LiveFrame f;
  f.input = "start";
  f.sha256 = std::string(64, 'b');
  study::Database d(db, false);
  auto s = d.prepare("INSERT INTO events (session, trial, t_ns, kind, detail) SELECT s.id, t.id, 1, 'frame', ?1 FROM sessions s "
                     "JOIN participants p ON p.id = s.participant JOIN trials t ON t.participant = p.id "
                     "WHERE p.participant = ?2 AND t.sequence = 1");
  s.bind(1, study::frameJson(f));
  s.bind(2, participant);
  s.step();
}

TEST(ReplayAdmin, ThePageListsTheReplayCommandOfEachTrialWithFrames) {
  const auto dir = freshDir("replay_admin");
  const std::string db = (dir / "study.db").string();
  ServedStudy server(studyData("serve_tiny.toml"), db, dir);
  PageClient page(server.port());
  const std::string admin = server.adminToken();
  const auto [status, token] = page.arrive("serve-tiny", "PROLIFIC_PID=p1&STUDY_ID=s1&SESSION_ID=x");
  ASSERT_EQ(status, 303);
  walk(page, token, page.api(token, "display", display()).body, 1);
  EXPECT_EQ(page.get("/admin/status.json?token=" + admin).body["replays"], nlohmann::json::array()) << "no frames yet";
  EXPECT_NE(page.raw("/admin?token=" + admin)->body.find("none yet"), std::string::npos);

  storeFrame(db, "p1");
  const nlohmann::json replays = page.get("/admin/status.json?token=" + admin).body["replays"];
  ASSERT_EQ(replays.size(), 1u) << replays.dump();
  EXPECT_EQ(replays[0]["participant"], "p1");
  EXPECT_EQ(replays[0]["trial"], 1);
  EXPECT_EQ(replays[0]["frames"], 1);
  const std::string command = "tlab replay '" + db + "' --participant 'p1' --trial 1 --html 'replay-p1-trial1.html'";
  EXPECT_EQ(replays[0]["command"], command);
  const auto html = page.raw("/admin?token=" + admin);
  ASSERT_EQ(html->status, 200);
  EXPECT_NE(html->body.find("<h2>Replays of interactive trials</h2>"), std::string::npos);
  EXPECT_NE(html->body.find("<code>" + command + "</code>"), std::string::npos) << html->body;
  EXPECT_EQ(page.raw("/admin/status.json?token=" + std::string(64, 'a'))->status, 403);
}

}  // namespace
}  // namespace tlab::testing
