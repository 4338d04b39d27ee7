// `tlab run` in a real GLFW window under Xvfb, driven with xdotool as a participant would: Space
// through the welcome and instruction screens, type the layer number and press Enter, click the
// labels met along the boundary and press Enter, click the target's place on the floor plan,
// press 4 in the questionnaire. The database then holds the three responses (scored correct), the questionnaire answer, onset events with the
// present-to-swap time, and the participant as finished. Prints the timing line of the run.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include <nlohmann/json.hpp>

#include "renderer/scene/scene_source.hpp"
#include "stimuli/scenes/stimulus_scenes.hpp"
#include "study/run/floor_plan.hpp"
#include "study/run/screen_layout.hpp"
#include "study/store/sqlite_database.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;
using tlab::study::Database;

namespace {

const std::string kTlab = TLAB_EXE;
bool haveTool(const std::string& name) { return runCommand("command -v " + name).exitCode == 0; }

void pause(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

struct StoredTrial {
  nlohmann::json question;
};

// The trials of the participant once the runner has stored its plan (polls up to ~20 s).
std::vector<StoredTrial> waitForTrials(const std::string& db) {
  for (int i = 0; i < 200; ++i) {
    try {
      Database d(db, false);
      auto s = d.prepare("SELECT question_json FROM trials ORDER BY sequence");
      std::vector<StoredTrial> out;
      while (s.step()) out.push_back({nlohmann::json::parse(s.text(0))});
      if (!out.empty()) return out;
    } catch (const std::exception&) {
    }
    pause(100);
  }
  return {};
}

// `tlab run EXPERIMENT` for one participant on its own Xvfb display (apart from window_cli_test's
// 90..189), with xdotool driving its window.
struct WindowSession {
  std::filesystem::path dir;
  std::string db, env, window;
  pid_t xvfb = -1, tlab = -1;

  WindowSession(const std::string& name, int displayBase, const std::string& experiment, const std::string& participant)
      : dir(freshDir(name)), db((dir / "study.db").string()) {
    const std::string display = ":" + std::to_string(displayBase + ::getpid() % 100);
    xvfb = spawnProcess({"Xvfb", display, "-screen", "0", "800x600x24"}, (dir / "xvfb.out").string(), (dir / "xvfb.err").string());
    pause(800);
    env = "DISPLAY=" + display;
    tlab = spawnProcess({kTlab, "run", studyData(experiment), "--participant", participant, "--db", db, "--size", "640x480"},
                        (dir / "run.out").string(), (dir / "run.err").string(), {env});
    const auto r = runCommand(env + " timeout 20 xdotool search --sync --name 'tlab run' | head -1");
    window = r.out.substr(0, r.out.find('\n'));
  }
  CommandResult xdo(const std::string& args) const { return runCommand(env + " xdotool " + args); }
  // Waits for tlab to end, stops Xvfb; tlab's exit code.
  int finish() {
    const int code = waitProcess(tlab);
    ::kill(xvfb, SIGTERM);
    waitProcess(xvfb);
    return code;
  }
  std::string out() const { return readText((dir / "run.out").string()); }
  std::string err() const { return readText((dir / "run.err").string()); }
};

}  // namespace

TEST(WindowRun, ParticipantAnswersByKeyboardAndClicksUnderXvfb) {
  if (!haveTool("Xvfb") || !haveTool("xdotool")) GTEST_SKIP() << "needs Xvfb and xdotool (scripts/setup.sh installs both)";
  WindowSession session("window_run", 300, "window.toml", "P'01; DROP TABLE trials");
  const std::string& db = session.db;
  const std::string& window = session.window;
  const auto xdo = [&](const std::string& args) { return session.xdo(args); };
  ASSERT_FALSE(window.empty()) << session.err();
  const auto trials = waitForTrials(db);
  ASSERT_EQ(trials.size(), 3u) << session.err();
  pause(500);

  xdo("key --window " + window + " space");  // welcome
  pause(400);
  xdo("key --window " + window + " space");  // task instructions
  pause(400);
  const std::string layer = trials[0].question["truth"].dump();
  xdo("key --window " + window + " Escape");  // pause: the paused time is left out of the RT
  pause(500);
  xdo("key --window " + window + " space");  // resume
  pause(200);
  xdo("type --window " + window + " " + layer);
  xdo("key --window " + window + " Return");
  pause(400);
  xdo("key --window " + window + " space");  // next task's instructions
  pause(400);
  // Click each label met along the boundary at its place on the screen, then Enter.
  const tlab::study::ScreenLayout layout = tlab::study::makeScreenLayout(640, 480, 160, 160);
  std::vector<std::string> expected;
  for (const auto& label : trials[1].question["truth"]) expected.push_back(label.get<std::string>());
  for (const auto& point : trials[1].question["points"]) {
    const std::string label = point["label"];
    if (std::find(expected.begin(), expected.end(), label) == expected.end()) continue;
    const glm::dvec2 screen = layout.toScreen({point["pixel"][0].get<double>(), point["pixel"][1].get<double>()});
    xdo("mousemove --window " + window + " " + std::to_string(int(screen.x)) + " " + std::to_string(int(screen.y)));
    pause(100);
    xdo("click --window " + window + " 1");
    pause(200);
  }
  xdo("key --window " + window + " Return");
  pause(400);
  xdo("key --window " + window + " space");  // next task's instructions
  pause(400);
  // Click the target's floor position on the plan beside the stimulus.
  const tlab::study::ScreenLayout planLayout = tlab::study::makeScreenLayoutWithPlan(640, 480, 160, 160);
  const auto scene = tlab::render::loadScene("builtin:walkthrough?seed=5", tlab::stimuli::allSceneSpecs());
  const tlab::study::FloorPlan plan = tlab::study::makeFloorPlan(scene, 160, 160);
  const auto truth = trials[2].question["truth"];
  const glm::dvec2 planPixel = plan.pixelOf({truth[0].get<double>(), plan.floorY, truth[1].get<double>()});
  const int clickX = int(planLayout.plan->x + planPixel.x * planLayout.plan->width / 160.0);
  const int clickY = int(planLayout.plan->y + planPixel.y * planLayout.plan->height / 160.0);
  xdo("mousemove --window " + window + " " + std::to_string(clickX) + " " + std::to_string(clickY));
  pause(100);
  xdo("click --window " + window + " 1");
  pause(400);
  xdo("key --window " + window + " 4");  // questionnaire
  pause(400);
  xdo("key --window " + window + " Return");  // confirm the answers
  pause(400);
  xdo("key --window " + window + " space");  // debrief
  const int code = session.finish();
  const std::string out = session.out();
  ASSERT_EQ(code, 0) << out << session.err();
  EXPECT_NE(out.find("session finished: 3 of 3 trials answered"), std::string::npos) << out;
  std::printf("%s", out.substr(out.find("timing:")).c_str());

  Database d(db, false);
  auto responses = d.prepare("SELECT t.task_id, r.raw_answer, r.correct, r.rt_seconds, r.response_ns - r.onset_ns FROM responses r "
                             "JOIN trials t ON t.id = r.trial ORDER BY t.sequence");
  ASSERT_TRUE(responses.step());
  EXPECT_EQ(responses.text(0), "layer");
  EXPECT_EQ(responses.text(1), layer);
  EXPECT_EQ(responses.integer(2), 1);
  EXPECT_GT(responses.real(3), 0.0);
  EXPECT_LT(responses.real(3), responses.integer(4) / 1e9 - 0.4);  // paused ≥ 0.5 s: not counted
  ASSERT_TRUE(responses.step());
  EXPECT_EQ(responses.text(0), "boundary");
  EXPECT_NEAR(responses.real(3), responses.integer(4) / 1e9, 1e-6);  // no pause: RT = response − onset
  std::string joined;
  for (const auto& l : expected) joined += (joined.empty() ? "" : ",") + l;
  EXPECT_EQ(responses.text(1), joined.empty() ? "none" : joined);
  EXPECT_EQ(responses.integer(2), 1);
  ASSERT_TRUE(responses.step());
  EXPECT_EQ(responses.text(0), "find");
  EXPECT_EQ(responses.integer(2), 1) << "clicked " << responses.text(1) << ", truth " << truth.dump();
  EXPECT_FALSE(responses.step());

  auto questionnaire = d.prepare("SELECT item, value FROM questionnaire_answers");
  ASSERT_TRUE(questionnaire.step());
  EXPECT_EQ(questionnaire.text(0), "ease");
  EXPECT_EQ(questionnaire.integer(1), 4);
  auto participant = d.prepare("SELECT participant, status FROM participants");
  ASSERT_TRUE(participant.step());
  EXPECT_EQ(participant.text(0), "P'01; DROP TABLE trials");
  EXPECT_EQ(participant.text(1), "finished");
  auto onsets = d.prepare("SELECT detail FROM events WHERE kind = 'onset' ORDER BY id");
  int count = 0;
  while (onsets.step()) {
    const auto detail = nlohmann::json::parse(onsets.text(0));
    EXPECT_GT(detail["present_ms"].get<double>(), 0.0);
    ++count;
  }
  EXPECT_EQ(count, 3);
  auto paused = d.prepare("SELECT count(*) FROM events WHERE kind IN ('pause', 'resume')");
  ASSERT_TRUE(paused.step());
  EXPECT_EQ(paused.integer(0), 2);
}

// An interactive trial (Elmqvist): the scene is rendered live while the participant orbits it by
// dragging and zooms with the arrow keys; every camera move is logged as an event, then the typed
// count is stored and scored.
TEST(WindowRun, ParticipantOrbitsALiveSceneUnderXvfb) {
  if (!haveTool("Xvfb") || !haveTool("xdotool")) GTEST_SKIP() << "needs Xvfb and xdotool (scripts/setup.sh installs both)";
  WindowSession session("window_live", 400, "live.toml", "L1");
  const std::string& db = session.db;
  const std::string& window = session.window;
  const auto xdo = [&](const std::string& args) { return session.xdo(args); };
  ASSERT_FALSE(window.empty()) << session.err();
  const auto trials = waitForTrials(db);
  ASSERT_EQ(trials.size(), 1u) << session.err();
  pause(500);
  xdo("key --window " + window + " space");  // welcome
  pause(400);
  xdo("key --window " + window + " space");  // task instructions
  pause(600);
  // Drag across the stimulus: orbit.
  xdo("mousemove --window " + window + " 320 240");
  xdo("mousedown --window " + window + " 1");
  for (int i = 1; i <= 4; ++i) {
    xdo("mousemove --window " + window + " " + std::to_string(320 + 15 * i) + " " + std::to_string(240 + 5 * i));
    pause(150);
  }
  xdo("mouseup --window " + window + " 1");
  pause(300);
  xdo("key --window " + window + " Up");  // zoom in
  pause(300);
  xdo("key --window " + window + " Left");  // turn
  pause(300);
  const std::string count = trials[0].question["truth"].dump();
  xdo("type --window " + window + " " + count);
  xdo("key --window " + window + " Return");
  pause(500);
  xdo("key --window " + window + " space");  // goodbye
  const int code = session.finish();
  ASSERT_EQ(code, 0) << session.out() << session.err();

  Database d(db, false);
  auto response = d.prepare("SELECT raw_answer, correct FROM responses");
  ASSERT_TRUE(response.step());
  EXPECT_EQ(response.text(0), count);
  EXPECT_EQ(response.integer(1), 1);
  auto cameras = d.prepare("SELECT detail FROM events WHERE kind = 'camera' ORDER BY id");
  std::vector<std::string> seen;
  while (cameras.step()) seen.push_back(cameras.text(0));
  ASSERT_GE(seen.size(), 3u) << "drags and two arrow keys";
  EXPECT_NE(seen.front(), seen.back());
  EXPECT_EQ(seen.front().rfind("eye=", 0), 0u) << seen.front();
}
