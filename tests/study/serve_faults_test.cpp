// Faults of `tlab serve` under load: the server is killed with SIGKILL four times while 8
// simulated participants (the load client, in this process) walk their sessions 4 at a time,
// each time right after the k-th acknowledged answer for a fixed k, and restarted on the same
// database and port. The participants retry as the page does (re-arriving through the link
// resumes them). Afterwards every acknowledged answer is stored exactly once with the answer
// sent, no trial has two responses, and every participant finished.
#include <gtest/gtest.h>

#include <memory>

#include <set>

#include "study/serve/load_client.hpp"
#include "tests/study/serve_test_support.hpp"

using namespace tlab::testing;

TEST(ServeFaults, KillNineDuringLoadLosesNothingAndEveryoneResumes) {
  const auto dir = freshDir("serve_faults");
  const std::string experiment = studyData("tiny.toml");
  const std::string db = (dir / "study.db").string();
  auto server = std::make_unique<ServedStudy>(experiment, db, dir);
  const std::set<int> killAfter = {5, 23, 41, 62};  // of 80 acknowledged answers
  int kills = 0;
  tlab::study::LoadOptions o;
  o.url = server->link();
  o.participants = 8;
  o.concurrency = 4;
  o.behaviour.thinkMs = 5.0;
  o.behaviour.retrySeconds = 120.0;  // a restart prepares the stimuli again (cached beside the database)
  o.seed = 11;
  o.onAck = [&](int acknowledged, const tlab::study::AckedTrial&) {
    if (!killAfter.count(acknowledged)) return;
    const int port = server->port();
    EXPECT_EQ(server->stop(SIGKILL), -SIGKILL);
    ++kills;
    server.reset();
    server = std::make_unique<ServedStudy>(experiment, db, dir, port);
  };
  const tlab::study::LoadResult r = tlab::study::runLoad(o);
  EXPECT_EQ(server->stop(SIGTERM), 0);
  EXPECT_EQ(kills, 4);
  ASSERT_EQ(r.failed, 0) << r.firstError;
  EXPECT_EQ(r.finished, 8);
  EXPECT_GT(r.reconnects, 0);

  const auto trials = exportedTrials(dir);
  for (const auto& a : r.acked) {
    const StoredTrial* t = storedTrialAt(trials, a.participant, a.phase, a.index);
    ASSERT_NE(t, nullptr) << a.participant << " " << a.phase << " trial " << a.index << " was acknowledged but is not stored";
    EXPECT_EQ(t->responded, 1) << a.participant << " " << a.phase << " trial " << a.index << " was acknowledged but has no response";
    EXPECT_EQ(t->rawAnswer, a.answer) << a.participant << " " << a.phase << " trial " << a.index;  // layer numbers: the JSON number is the text
  }
  std::map<std::string, int> perParticipant;
  for (const auto& [key, t] : trials) {
    EXPECT_EQ(t.rows, 1) << key.first << " trial " << key.second << " has " << t.rows << " responses";
    EXPECT_EQ(t.responded, 1) << key.first << " trial " << key.second << " has no response";
    EXPECT_EQ(t.status, "finished") << key.first;
    ++perParticipant[key.first];
  }
  EXPECT_EQ(perParticipant.size(), 8u);
  EXPECT_GE(r.acknowledged, 80 - 4 * 4) << "at most one unacknowledged answer per participant in flight per kill";
  std::printf("acknowledged %d of 80 answers, %d reconnections, 4 kills\n", r.acknowledged, r.reconnects);
}
