// Crash safety: a simulated session is killed with SIGKILL at random points (more than 20 times)
// and resumed each time. No acknowledged response (printed only after its transaction committed)
// may be lost or duplicated, every trial ends with exactly one response, the responses follow the
// planned order, and the final data equal those of an uninterrupted run with the same seeds.
#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <random>
#include <thread>

#include "study/sqlite_database.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;
using tlab::study::Database;

namespace {

const std::string kTlab = TLAB_EXE;
constexpr int kParticipants = 6;
constexpr int kTrialsPerParticipant = 12;

struct StoredResponse {
  std::int64_t responseId = 0;
  std::string answer;
  double rt = -1;
  int correct = 0;
};

// (participant, sequence) → response; also counts responses per trial.
std::map<std::pair<std::string, int>, StoredResponse> readResponses(const std::string& db, int& duplicates, int& trials) {
  Database d(db, false);
  auto s = d.prepare(
      "SELECT p.participant, t.sequence, r.id, r.raw_answer, r.rt_seconds, r.correct, "
      "(SELECT count(*) FROM responses r2 WHERE r2.trial = t.id) FROM trials t JOIN participants p ON p.id = t.participant "
      "LEFT JOIN responses r ON r.trial = t.id ORDER BY p.participant, t.sequence");
  std::map<std::pair<std::string, int>, StoredResponse> out;
  duplicates = 0;
  trials = 0;
  while (s.step()) {
    ++trials;
    if (s.integer(6) != 1) ++duplicates;
    if (s.isNull(2)) continue;
    out[{s.text(0), int(s.integer(1))}] = {s.integer(2), s.isNull(3) ? "(missing)" : s.text(3), s.isNull(4) ? -1 : s.real(4),
                                           int(s.integer(5))};
  }
  return out;
}

std::vector<std::string> simulateArgs(const std::string& db) {
  return {kTlab, "simulate", studyData("crash.toml"), "--participants", std::to_string(kParticipants), "--db", db, "--resume",
          "--trials", "--pace", "0.002"};
}

}  // namespace

TEST(CrashSafety, SigkillAtRandomPointsLosesNothingAndDuplicatesNothing) {
  const auto dir = freshDir("crash");
  const std::string db = (dir / "crash.db").string(), reference = (dir / "reference.db").string();
  ASSERT_EQ(runCommand(kTlab + " simulate " + studyData("crash.toml") + " --participants " + std::to_string(kParticipants) + " --db " +
                       reference).exitCode,
            0);

  std::mt19937 random(20261122);
  std::map<std::pair<std::string, int>, std::string> acknowledged;
  int kills = 0, runs = 0, duplicateAcks = 0;
  bool finished = false;
  while (!finished) {
    ASSERT_LT(runs, 200) << "the session never finished";
    const std::string out = (dir / ("run" + std::to_string(runs) + ".out")).string();
    const pid_t pid = spawnProcess(simulateArgs(db), out, out + ".err");
    ++runs;
    int code;
    if (kills < 24) {
      if (runs % 3 != 0) {
        // Anywhere, including start-up, planning and rendering.
        std::this_thread::sleep_for(std::chrono::milliseconds(random() % 300));
      } else {
        // Inside a running session: after 1-2 acknowledged responses, plus up to 30 ms.
        const std::size_t target = random() % 2;
        for (int i = 0; i < 2500 && parseAcks(readText(out)).size() < target + 1; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(2));
        std::this_thread::sleep_for(std::chrono::milliseconds(random() % 30));
      }
      ::kill(pid, SIGKILL);
      code = waitProcess(pid);
      if (code == -SIGKILL) ++kills;
    } else {
      code = waitProcess(pid);
    }
    for (const auto& a : parseAcks(readText(out)))
      if (!acknowledged.emplace(std::make_pair(a.participant, a.sequence), a.answer).second) ++duplicateAcks;
    if (code == 0) finished = readText(out).find("simulated ") != std::string::npos;
    else ASSERT_EQ(code, -SIGKILL) << readText(out + ".err");
  }
  EXPECT_GE(kills, 20);
  EXPECT_EQ(duplicateAcks, 0) << "a trial was acknowledged twice (answered again after a resume)";

  int duplicates = 0, trials = 0;
  const auto stored = readResponses(db, duplicates, trials);
  EXPECT_EQ(trials, kParticipants * kTrialsPerParticipant);
  EXPECT_EQ(duplicates, 0) << "every trial must have exactly one response";
  EXPECT_EQ(stored.size(), std::size_t(kParticipants * kTrialsPerParticipant));
  for (const auto& [key, answer] : acknowledged) {
    const auto it = stored.find(key);
    ASSERT_NE(it, stored.end()) << "acknowledged response lost: " << key.first << " #" << key.second;
    EXPECT_EQ(it->second.answer, answer) << key.first << " #" << key.second;
  }
  // The order continues: response rows were written in the planned order, participant by participant.
  std::int64_t last = 0;
  for (const auto& [key, r] : stored) {
    EXPECT_GT(r.responseId, last) << key.first << " #" << key.second;
    last = r.responseId;
  }
  // Resumed sessions answer exactly as an uninterrupted one.
  int refDuplicates = 0, refTrials = 0;
  const auto expected = readResponses(reference, refDuplicates, refTrials);
  ASSERT_EQ(expected.size(), stored.size());
  for (const auto& [key, r] : expected) {
    EXPECT_EQ(stored.at(key).answer, r.answer) << key.first << " #" << key.second;
    EXPECT_EQ(stored.at(key).correct, r.correct);
    EXPECT_DOUBLE_EQ(stored.at(key).rt, r.rt);
  }
  // The kills hit running sessions (sessions left without an end), not only start-ups.
  Database d(db, false);
  auto open = d.prepare("SELECT count(*) FROM sessions WHERE ended_at IS NULL");
  ASSERT_TRUE(open.step());
  EXPECT_GE(open.integer(0), 5);
  auto finishedCount = d.prepare("SELECT count(*) FROM participants WHERE status = 'finished'");
  ASSERT_TRUE(finishedCount.step());
  EXPECT_EQ(finishedCount.integer(0), kParticipants);
  // After-block questionnaires: one per block and participant, none lost or repeated by resuming.
  auto questionnaires = d.prepare("SELECT count(*), count(DISTINCT participant || '/' || block) FROM questionnaire_answers");
  ASSERT_TRUE(questionnaires.step());
  EXPECT_EQ(questionnaires.integer(0), kParticipants * 4);
  EXPECT_EQ(questionnaires.integer(1), kParticipants * 4);
}
