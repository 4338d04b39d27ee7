// Crash safety: a simulated session is killed with SIGKILL 24 times at points the test chooses
// with a seeded random generator — at start-up, during stimulus preparation, right after a
// stimulus onset was committed, inside a response transaction before its COMMIT, and after K
// acknowledged responses — and resumed each time. The process stops itself at the chosen fault
// point (TLAB_STOP_AT, study/store/fault_point.hpp) and is killed there, so every kill lands where it
// was meant to on any machine, however fast. No acknowledged response (printed only after its transaction committed)
// may be lost or duplicated, every trial ends with exactly one response, the responses follow the
// planned order, and the final data equal those of an uninterrupted run with the same seeds.
#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <random>
#include <thread>

#include "study/store/sqlite_database.hpp"
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
          "--trials"};
}

// Runs tlab with TLAB_STOP_AT=`point`; when it stops there, kills it. The exit code, or -SIGKILL.
int runUntil(const std::vector<std::string>& args, const std::string& point, const std::string& out) {
  const std::string env = "TLAB_STOP_AT=" + point;
  const pid_t pid = spawnProcess(args, out, out + ".err", {env});
  int status = 0;
  ::waitpid(pid, &status, WUNTRACED);
  if (WIFSTOPPED(status)) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

// A fault point the run is sure to reach while `remaining` responses are still to come.
std::string chooseKillPoint(std::mt19937& random, int run, int remaining) {
  const int most = std::max(1, std::min(4, remaining - 1));
  const int k = 1 + int(random() % std::uint32_t(most));
  switch (run % 5) {
    case 0: return "open";
    case 1: return "prepare:" + std::to_string(k);
    case 2: return "onset:" + std::to_string(k);
    case 3: return "commit:" + std::to_string(k);
    default: return "ack:" + std::to_string(k);
  }
}

using Acknowledged = std::map<std::pair<std::string, int>, std::string>;  // (participant, sequence) → answer

// Runs the simulation, killed 24 times at points chosen with a seeded generator and resumed, until
// a run finishes; every acknowledged response is collected and none may be acknowledged twice.
void killUntilFinished(const std::filesystem::path& dir, const std::string& db, Acknowledged& acknowledged) {
  std::mt19937 random(20261122);
  std::map<std::string, int> killsAt;
  int kills = 0, runs = 0, duplicateAcks = 0;
  bool finished = false;
  while (!finished) {
    ASSERT_LT(runs, 60) << "the session never finished";
    const std::string out = (dir / ("run" + std::to_string(runs) + ".out")).string();
    const int remaining = kParticipants * kTrialsPerParticipant - int(acknowledged.size());
    const std::string point = kills < 24 && remaining > 1 ? chooseKillPoint(random, runs, remaining) : "";
    const int code = runUntil(simulateArgs(db), point, out);
    ++runs;
    for (const auto& a : parseAcks(readText(out)))
      if (!acknowledged.emplace(std::make_pair(a.participant, a.sequence), a.answer).second) ++duplicateAcks;
    if (code == -SIGKILL) {
      ++kills;
      ++killsAt[point.substr(0, point.find(':'))];
      continue;
    }
    ASSERT_EQ(code, 0) << point << ": " << readText(out + ".err");
    finished = readText(out).find("simulated ") != std::string::npos;
  }
  EXPECT_EQ(kills, 24);
  for (const char* kind : {"open", "prepare", "onset", "commit", "ack"}) EXPECT_GE(killsAt[kind], 4) << kind;
  EXPECT_EQ(duplicateAcks, 0) << "a trial was acknowledged twice (answered again after a resume)";
}

// Every trial has exactly one response, every acknowledged one among them, written in the planned
// order, and resumed sessions answer exactly as the uninterrupted reference run.
void expectResponsesAsReference(const std::string& db, const std::string& reference, const Acknowledged& acknowledged) {
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
}

// The session log after the kills: sessions, onsets, participants and questionnaires.
void expectSessionLog(const std::string& db) {
  // The kills hit running sessions (sessions left without an end), not only start-ups.
  EXPECT_GE(queryCount(db, "SELECT count(*) FROM sessions WHERE ended_at IS NULL"), 5);
  // Sessions killed while running are marked as interrupted and resumed by the next one.
  EXPECT_GE(queryCount(db, "SELECT count(*) FROM sessions WHERE end_reason = 'interrupted' AND resumed_by IS NOT NULL"), 5);
  // Every stimulus shown was logged when it was shown: each answered trial has an onset before its
  // response, and trials whose session was killed after the onset were shown again and say so.
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM responses r WHERE NOT EXISTS "
                     "(SELECT 1 FROM events e WHERE e.trial = r.trial AND e.kind = 'onset' AND e.id < "
                     "(SELECT min(id) FROM events e2 WHERE e2.trial = r.trial AND e2.kind = 'response'))"),
            0);
  EXPECT_GE(queryCount(db, "SELECT count(*) FROM events WHERE kind = 'onset' AND detail LIKE '%shown again%'"),
            4);  // at least the onset and commit kills
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM participants WHERE status = 'finished'"), kParticipants);
  // After-block questionnaires: one per block and participant, none lost or repeated by resuming.
  const std::string questionnaires =
      "SELECT count(*), count(DISTINCT participant || '/' || block) FROM questionnaire_answers";
  EXPECT_EQ(queryCount(db, questionnaires, 0), kParticipants * 4);
  EXPECT_EQ(queryCount(db, questionnaires, 1), kParticipants * 4);
}

}  // namespace

TEST(CrashSafety, SigkillAtChosenPointsLosesNothingAndDuplicatesNothing) {
  const auto dir = freshDir("crash");
  const std::string db = (dir / "crash.db").string(), reference = (dir / "reference.db").string();
  ASSERT_EQ(runCommand(kTlab + " simulate " + studyData("crash.toml") + " --participants " + std::to_string(kParticipants) + " --db " +
                       reference).exitCode,
            0);
  Acknowledged acknowledged;
  ASSERT_NO_FATAL_FAILURE(killUntilFinished(dir, db, acknowledged));
  ASSERT_NO_FATAL_FAILURE(expectResponsesAsReference(db, reference, acknowledged));
  expectSessionLog(db);
}
