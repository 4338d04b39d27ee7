// End-to-end: `tlab task probe` and `tlab task check` as a user runs them.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
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
  // A setting outside what its task declared is refused before anything is probed (attempts=1e12
  // used to reach an int conversion and end in "found only 0 of 1").
  const CommandResult huge = run("task probe builtin:sphere --task layer-index --count 1 --set attempts=1e12");
  EXPECT_EQ(huge.exitCode, 1);
  EXPECT_NE(huge.output.find("tlab: error: task 'layer-index': setting 'attempts' = 1e12: expected a whole number in [1, 1000000]"),
            std::string::npos)
      << huge.output;
  EXPECT_NE(list.output.find("--set attempts=400  candidate probes tried per question before giving up (a whole number in [1, 1000000])"),
            std::string::npos)
      << list.output;
}


namespace shape {

// "eye=X,Y,Z target=X,Y,Z ...": the named vector of the camera text `tlab task probe` prints.
std::array<double, 3> cameraVector(const std::string& camera, const std::string& name) {
  std::array<double, 3> v{};
  const auto at = camera.find(name + "=");
  EXPECT_NE(at, std::string::npos) << camera;
  std::sscanf(camera.c_str() + at + name.size() + 1, "%lf,%lf,%lf", &v[0], &v[1], &v[2]);
  return v;
}

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
std::array<double, 3> minus(const std::array<double, 3>& a, const std::array<double, 3>& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
std::array<double, 3> vec(const nlohmann::json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

TEST(TaskCli, GaugeFigureNormalsAreRadialToOneInAMillionAndFaceTheViewer) {
  const CommandResult probe = run("task probe 'builtin:nested-spheres?n=3' --task gauge-figure --count 5 --json");
  ASSERT_EQ(probe.exitCode, 0) << probe.output;
  const auto j = nlohmann::json::parse(probe.output);
  const auto eye = cameraVector(j["camera"], "eye");
  ASSERT_EQ(j["questions"].size(), 5u);
  for (const auto& q : j["questions"]) {
    EXPECT_EQ(q["answer_kind"], "direction");
    const auto p = vec(q["points"][0]["world"]), n = vec(q["truth"]);
    const double r = std::sqrt(dot(p, p));
    const double facing = dot(n, minus(eye, p));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(std::abs(n[std::size_t(i)]), std::abs(p[std::size_t(i)] / r), 1e-6);
    EXPECT_NEAR(std::abs(dot(n, p) / r), 1.0, 1e-6);
    EXPECT_GT(facing, 0.0);
    EXPECT_TRUE(q["measurements"].contains("slant") && q["measurements"].contains("tilt"));
  }
  // The truth typed back scores 0°; a typed direction 90° away scores 90° (and is wrong).
  const auto& q1 = j["questions"][0];
  const auto n = vec(q1["truth"]);
  char typed[160];
  std::snprintf(typed, sizeof typed, "%.9f,%.9f,%.9f", n[0], n[1], n[2]);
  const CommandResult right = run("task check 'builtin:nested-spheres?n=3' --task gauge-figure --question 1 --json --answer " + std::string(typed));
  ASSERT_EQ(right.exitCode, 0) << right.output;
  const auto r = nlohmann::json::parse(right.output)["score"];
  EXPECT_TRUE(r["correct"].get<bool>());
  EXPECT_NEAR(r["error"].get<double>(), 0.0, 1e-6);
  const std::array<double, 3> across = std::abs(n[0]) < 0.9 ? std::array<double, 3>{0, -n[2], n[1]} : std::array<double, 3>{-n[1], n[0], 0};
  std::snprintf(typed, sizeof typed, "%.9f,%.9f,%.9f", across[0], across[1], across[2]);
  const auto wrong = nlohmann::json::parse(run("task check 'builtin:nested-spheres?n=3' --task gauge-figure --question 1 --json --answer " + std::string(typed)).output)["score"];
  EXPECT_NEAR(wrong["error"].get<double>(), 90.0, 1e-6);
  EXPECT_FALSE(wrong["correct"].get<bool>());
  const CommandResult bad = run("task check 'builtin:nested-spheres?n=3' --task gauge-figure --question 1 --answer 1,2");
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.output.find("expected a direction 'x,y,z'"), std::string::npos) << bad.output;
}

TEST(TaskCli, RelativeDepthTruthIsTheNearerPointAlongTheView) {
  const CommandResult probe = run("task probe 'builtin:nested-spheres?n=3' --task relative-depth --count 6 --set layer-b=2 --json");
  ASSERT_EQ(probe.exitCode, 0) << probe.output;
  const auto j = nlohmann::json::parse(probe.output);
  const auto eye = cameraVector(j["camera"], "eye"), target = cameraVector(j["camera"], "target");
  const auto forward = minus(target, eye);
  for (const auto& q : j["questions"]) {
    const double a = dot(minus(vec(q["points"][0]["world"]), eye), forward), b = dot(minus(vec(q["points"][1]["world"]), eye), forward);
    EXPECT_EQ(q["truth"], a < b ? "A" : "B");
  }
}

TEST(TaskCli, ListShowsTheShapeTasksAndTheirSettings) {
  const CommandResult list = run("task list");
  ASSERT_EQ(list.exitCode, 0);
  for (const char* s : {"gauge-figure:", "--set layer=1", "--set gauge-radius-px=", "relative-depth:", "--set min-depth-gap="})
    EXPECT_NE(list.output.find(s), std::string::npos) << s;
}

TEST(TaskCli, StimulusSetsCarryTheShapeTasksWithTheirTruthAndSayAGaugeCannotBePrinted) {
  const std::string out = "task_cli_shape_set";
  std::system(("rm -rf " + out).c_str());
  const CommandResult r = run("stimuli " + std::string(TLAB_SOURCE_DIR) + "/tests/tasks/data/shape-set.toml -o " + out + " --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(out + "/manifest.json");
  const auto manifest = nlohmann::json::parse(in);
  int gauges = 0, depths = 0;
  for (const auto& s : manifest["stimuli"]) {
    const auto& truth = s["question"]["ground_truth"];
    if (truth["task"] == "gauge-figure") {
      ++gauges;
      EXPECT_EQ(truth["answer_kind"], "direction");
      EXPECT_EQ(truth["points"][0]["role"], "gauge");
      EXPECT_NE(s["question"]["answer_format"].get<std::string>().find("answer it in the window or the browser"), std::string::npos);
    } else if (truth["task"] == "relative-depth") {
      ++depths;
      EXPECT_EQ(truth["answer_kind"], "label");
      EXPECT_EQ(truth["points"].size(), 2u);
    }
  }
  EXPECT_EQ(gauges, 2);  // two styles
  EXPECT_EQ(depths, 2);
  EXPECT_TRUE(std::ifstream(out + "/booklet.pdf").good());
}

}  // namespace shape
}  // namespace
