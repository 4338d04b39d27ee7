// End-to-end: `tlab task probe` and `tlab task check` as a user runs them.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

namespace {

struct CommandResult {
  int exitCode;
  std::string output;  // stdout and stderr
};

CommandResult run(const std::string& arguments) {
  const std::string command = std::string(TLAB_EXE) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return CommandResult{-1, ""};
  std::string out;
  std::array<char, 4096> buffer;
  while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
  const int status = pclose(pipe);
  return CommandResult{WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

TEST(TaskCli, ProbePrintsQuestionsWithGroundTruthAndCheckScoresThem) {
  const CommandResult probe = run("task probe builtin:open-cylinders --task layer-index --count 3 --seed 5 --size 400x300 --json");
  ASSERT_EQ(probe.exitCode, 0) << probe.output;
  const auto j = nlohmann::json::parse(probe.output);
  ASSERT_EQ(j["questions"].size(), 3u);
  const auto& q2 = j["questions"][1];
  EXPECT_EQ(q2["task"], "layer-index");
  EXPECT_EQ(q2["number"], 2);
  EXPECT_EQ(q2["points"][0]["label"], "A");
  const int truth = q2["truth"].get<int>();
  EXPECT_GE(truth, 1);

  const std::string check = "task check builtin:open-cylinders --task layer-index --seed 5 --size 400x300 --question 2 --json";
  const CommandResult right = run(check + " --answer " + std::to_string(truth));
  ASSERT_EQ(right.exitCode, 0) << right.output;
  const auto r = nlohmann::json::parse(right.output);
  EXPECT_EQ(r["question"]["points"], q2["points"]);  // the same question, regenerated
  EXPECT_EQ(r["score"]["correct"], true);
  EXPECT_EQ(r["score"]["score"], 1.0);

  const auto wrong = nlohmann::json::parse(run(check + " --answer " + std::to_string(truth + 1)).output);
  EXPECT_EQ(wrong["score"]["correct"], false);
  const auto late = nlohmann::json::parse(run(check + " --answer " + std::to_string(truth) + " --time 500").output);
  EXPECT_EQ(late["score"]["answered"], false);
  EXPECT_EQ(late["score"]["score"], 0.0);
}

TEST(TaskCli, FollowBoundaryCheckReportsPartialCredit) {
  const CommandResult probe = run("task probe builtin:open-cylinders --task follow-boundary --count 1 --seed 2 --json");
  ASSERT_EQ(probe.exitCode, 0) << probe.output;
  const auto q = nlohmann::json::parse(probe.output)["questions"][0];
  std::string answer;
  for (const auto& l : q["truth"]) {
    if (!answer.empty()) answer += ',';
    answer += l.get<std::string>();
  }
  const CommandResult check = run("task check builtin:open-cylinders --task follow-boundary --seed 2 --question 1 --json --answer '" +
                        (answer.empty() ? std::string("none") : answer) + "'");
  ASSERT_EQ(check.exitCode, 0) << check.output;
  const auto s = nlohmann::json::parse(check.output)["score"];
  EXPECT_EQ(s["correct"], true);
  EXPECT_EQ(s["partial_credit"], 1.0);
}

TEST(TaskCli, BadAnswerAndUnknownTaskAreOneLineErrors) {
  const CommandResult bad = run("task check builtin:open-cylinders --task layer-index --seed 5 --question 1 --answer front");
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.output.find("expected a layer number"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("'front'"), std::string::npos) << bad.output;
  const CommandResult unknown = run("task probe builtin:sphere --task layers --count 1");
  EXPECT_EQ(unknown.exitCode, 1);
  EXPECT_NE(unknown.output.find("known: layer-index"), std::string::npos) << unknown.output;
  const CommandResult list = run("task list");
  EXPECT_EQ(list.exitCode, 0);
  EXPECT_NE(list.output.find("euclidean-trap-share"), std::string::npos);
}

}  // namespace
