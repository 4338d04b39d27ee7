// End to end: `tlab serve` on the tiny experiment and `tlab loadtest` with 8 simulated
// participants, 4 at a time, thinking about 10 ms (exponential); `tlab export --csv` must then
// hold every participant finished, with every trial answered exactly once.
#include <gtest/gtest.h>

#include <httplib.h>

#include <nlohmann/json.hpp>

#include "tests/study/serve_test_support.hpp"

using namespace tlab::testing;

TEST(ServeLoad, EightParticipantsFourAtATimeFinishWithEveryTrialAnsweredOnce) {
  const auto dir = freshDir("serve_load");
  ServedStudy server(studyData("tiny.toml"), (dir / "study.db").string(), dir);
  const CommandResult load = runCommand(commandLine({TLAB_EXE, "loadtest", server.link(), "--participants", "8", "--concurrency", "4", "--think",
                                                     "10", "--seed", "3"}));
  EXPECT_EQ(server.stop(SIGTERM), 0);
  ASSERT_EQ(load.exitCode, 0) << load.out << load.err;
  EXPECT_NE(load.out.find("participants: 8 finished, 0 failed"), std::string::npos) << load.out;
  EXPECT_NE(load.out.find("responses acknowledged: 80 "), std::string::npos) << load.out;  // 10 trials each
  EXPECT_NE(load.out.find("answer -> acknowledgement (ms, n=80): p50 "), std::string::npos) << load.out;

  const auto trials = exportedTrials(dir);
  std::map<std::string, int> perParticipant;
  for (const auto& [key, t] : trials) {
    EXPECT_EQ(t.rows, 1) << key.first << " trial " << key.second << " has " << t.rows << " responses";
    EXPECT_EQ(t.responded, 1) << key.first << " trial " << key.second;
    EXPECT_EQ(t.status, "finished") << key.first;
    ++perParticipant[key.first];
  }
  ASSERT_EQ(perParticipant.size(), 8u);
  for (const auto& [participant, n] : perParticipant) EXPECT_EQ(n, 10) << participant;
}

TEST(ServeLoad, AFailedParticipantExitsOneWithTheFirstError) {
  const auto dir = freshDir("serve_load_fail");
  ServedStudy server(studyData("tiny.toml"), (dir / "study.db").string(), dir);
  const std::string wrongExperiment = server.link().substr(0, server.link().rfind('/') + 1) + "no-such-study";
  const CommandResult load = runCommand(commandLine({TLAB_EXE, "loadtest", wrongExperiment, "--participants", "2", "--concurrency", "2"}));
  EXPECT_EQ(server.stop(SIGTERM), 0);
  EXPECT_EQ(load.exitCode, 1);
  EXPECT_NE(load.out.find("participants: 0 finished, 2 failed"), std::string::npos) << load.out;
  EXPECT_NE(load.err.find("tlab: error: participant load-001: GET /s/no-such-study?pid=load-001: HTTP 404"), std::string::npos) << load.err;
}

// The end screen holds the completion code: a page reloaded after the end (POST /display again)
// must show it again, not start the finished session anew (which ended on an error screen).
TEST(ServeLoad, APageReloadedAfterTheEndStillShowsTheEndScreen) {
  const auto dir = freshDir("serve_reload_end");
  ServedStudy server(studyData("tiny.toml"), (dir / "study.db").string(), dir);
  httplib::Client client("127.0.0.1", server.port());
  const auto arrived = client.Get("/s/tiny?pid=load-001");  // this page's token; the load client finishes its session
  ASSERT_TRUE(arrived);
  ASSERT_EQ(arrived->status, 303);
  const std::string api = "/api/" + arrived->get_header_value("Location").substr(3);
  const CommandResult load = runCommand(commandLine({TLAB_EXE, "loadtest", server.link(), "--participants", "1", "--think", "0"}));
  ASSERT_EQ(load.exitCode, 0) << load.out << load.err << server.stderrText();
  const auto again = client.Get("/s/tiny?pid=load-001");
  ASSERT_TRUE(again);
  EXPECT_EQ(again->status, 409) << "a finished participant's link says so" << server.stderrText();
  const auto shown = client.Post((api + "/display").c_str(), "{}", "application/json");
  ASSERT_TRUE(shown);
  EXPECT_EQ(nlohmann::json::parse(shown->body).value("kind", ""), "end");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // a restarted walk would have failed by now
  const auto now = client.Get((api + "/screen").c_str());
  ASSERT_TRUE(now);
  EXPECT_EQ(nlohmann::json::parse(now->body).value("kind", ""), "end") << now->body << server.stderrText();
  EXPECT_EQ(server.stop(SIGTERM), 0);
}

// Live views under load (issue #30): two participants explore the walk and the orbit trial of
// live_online.toml at once, input after input as fast as frames come back, and answer; every frame
// they received is a stored "frame" event, and the frames a second and input → frame are printed.
TEST(ServeLoad, TwoParticipantsExploreLiveTrialsAndEveryFrameTheyGotIsLogged) {
  const auto dir = freshDir("serve_load_live");
  ServedStudy server(studyData("live_online.toml"), (dir / "study.db").string(), dir);
  const CommandResult load = runCommand(commandLine({TLAB_EXE, "loadtest", server.link(), "--participants", "2", "--concurrency", "2", "--think",
                                                     "0", "--live-seconds", "0.5", "--param", "PROLIFIC_PID"}));
  EXPECT_EQ(server.stop(SIGTERM), 0);
  ASSERT_EQ(load.exitCode, 0) << load.out << load.err;
  EXPECT_NE(load.out.find("participants: 2 finished, 0 failed"), std::string::npos) << load.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(load.out, m, std::regex("live frames: ([0-9]+); frames/s per participant: min [0-9.]+"))) << load.out;
  const long frames = std::stol(m[1]);
  EXPECT_GE(frames, 4) << "at least the start view of each live trial of each participant";
  EXPECT_NE(load.out.find("live input -> frame (ms, n=" + std::to_string(frames) + "): p50 "), std::string::npos) << load.out;
  EXPECT_NE(load.out.find("live first frame of a trial (ms, n=4): p50 "), std::string::npos) << "two participants, two live trials each" << load.out;
  // Every stage of a frame on the server, in the order it runs (Server-Timing).
  EXPECT_TRUE(std::regex_search(load.out, std::regex("live frame on the server \\(ms, p50/p95\\):  parse [0-9.]+/[0-9.]+  wait [0-9.]+/[0-9.]+  "
                                                     "build [0-9.]+/[0-9.]+  steer [0-9.]+/[0-9.]+  render [0-9.]+/[0-9.]+  hash [0-9.]+/[0-9.]+  "
                                                     "encode [0-9.]+/[0-9.]+  log [0-9.]+/[0-9.]+  total [0-9.]+/[0-9.]+\n")))
      << load.out;
  const auto db = (dir / "study.db").string();
  EXPECT_EQ(queryCount(db, "SELECT COUNT(*) FROM events WHERE kind = 'frame'"), frames) << "every frame received is logged, no other";
}
