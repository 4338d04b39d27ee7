// End to end: `tlab serve` on the tiny experiment and `tlab loadtest` with 8 simulated
// participants, 4 at a time, thinking 0-20 ms; `tlab export --csv` must then hold every
// participant finished, with every trial answered exactly once.
#include <gtest/gtest.h>

#include "tests/study/serve_test_support.hpp"

using namespace tlab::testing;

TEST(ServeLoad, EightParticipantsFourAtATimeFinishWithEveryTrialAnsweredOnce) {
  const auto dir = freshDir("serve_load");
  const ServeProcess server = startServe(studyData("tiny.toml"), dir, 0, "1");
  ASSERT_GT(server.port, 0);
  const CommandResult load = runCommand(commandLine({TLAB_EXE, "loadtest", server.link, "--participants", "8", "--concurrency", "4", "--think",
                                                     "10", "--seed", "3"}));
  EXPECT_EQ(stopServe(server), 0);
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
  const ServeProcess server = startServe(studyData("tiny.toml"), dir, 0, "1");
  ASSERT_GT(server.port, 0);
  const std::string wrongExperiment = server.link.substr(0, server.link.rfind('/') + 1) + "no-such-study";
  const CommandResult load = runCommand(commandLine({TLAB_EXE, "loadtest", wrongExperiment, "--participants", "2", "--concurrency", "2"}));
  EXPECT_EQ(stopServe(server), 0);
  EXPECT_EQ(load.exitCode, 1);
  EXPECT_NE(load.out.find("participants: 0 finished, 2 failed"), std::string::npos) << load.out;
  EXPECT_NE(load.err.find("tlab: error: participant load-001: GET /s/no-such-study?pid=load-001: HTTP 404"), std::string::npos) << load.err;
}
