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
#include "study/store/sqlite_database.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/study/window_session.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;
using tlab::study::Database;

namespace {

// Moves the pointer to (x, y) of the window and clicks there.
void clickAt(const WindowSession& session, int x, int y) {
  session.xdo("mousemove --window " + session.window + " " + std::to_string(x) + " " + std::to_string(y));
  pause(100);
  session.xdo("click --window " + session.window + " 1");
}

// Clicks each label met along the boundary where the window logged it at the trial's onset, then
// Enter; the labels.
std::vector<std::string> clickBoundaryLabels(const WindowSession& session, const StoredTrial& trial, const nlohmann::json& layout) {
  std::vector<std::string> expected;
  for (const auto& label : trial.question["truth"]) expected.push_back(label.get<std::string>());
  for (const auto& point : trial.question["points"]) {
    const std::string label = point["label"];
    if (std::find(expected.begin(), expected.end(), label) == expected.end()) continue;
    const auto& at = layout["labels"][label];
    clickAt(session, int(at[0].get<double>()), int(at[1].get<double>()));
    pause(200);
  }
  press(session, "Return", 400);
  return expected;
}

// Clicks the target's floor position on the plan beside the stimulus, where the window logged the
// plan at the trial's onset.
void clickFloorTarget(const WindowSession& session, const nlohmann::json& truth, const nlohmann::json& layout) {
  const auto& rect = layout["plan"];  // x, y, width, height
  const auto scene = tlab::render::loadScene("builtin:walkthrough?seed=5", tlab::stimuli::allSceneSpecs());
  const tlab::study::FloorPlan plan = tlab::study::makeFloorPlan(scene, 160, 160);
  const glm::dvec2 planPixel = plan.pixelOf({truth[0].get<double>(), plan.floorY, truth[1].get<double>()});
  const int clickX = int(rect[0].get<double>() + planPixel.x * rect[2].get<double>() / 160.0);
  const int clickY = int(rect[1].get<double>() + planPixel.y * rect[3].get<double>() / 160.0);
  clickAt(session, clickX, clickY);
  pause(400);
}

// The three responses as given: the typed layer (its RT without the pause), the boundary labels
// and the floor click, all scored correct.
void expectResponses(const std::string& db, const std::string& layer, const std::vector<std::string>& expected,
                     const nlohmann::json& truth) {
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
}

// The questionnaire answer, the participant (its id stored verbatim) finished, three onsets with
// their present time, and the pause and resume.
void expectSessionRecords(const std::string& db) {
  Database d(db, false);
  auto questionnaire = d.prepare("SELECT item, value FROM questionnaire_answers");
  ASSERT_TRUE(questionnaire.step());
  EXPECT_EQ(questionnaire.text(0), "ease");
  EXPECT_EQ(questionnaire.integer(1), 4);
  auto participant = d.prepare("SELECT participant, status FROM participants");
  ASSERT_TRUE(participant.step());
  EXPECT_EQ(participant.text(0), "P'01; DROP TABLE trials");
  EXPECT_EQ(participant.text(1), "finished");
  auto onsets = d.prepare("SELECT detail FROM events WHERE kind = 'onset' ORDER BY id");
  int onsetCount = 0;
  while (onsets.step()) {
    const auto detail = nlohmann::json::parse(onsets.text(0));
    EXPECT_GT(detail["present_ms"].get<double>(), 0.0);
    // The answer band spans the window's bottom, below the stimulus (and the plan), and holds the buttons.
    const auto& band = detail["answer"];
    const int bandTop = band[1].get<int>(), canvasHeight = detail["canvas"][1].get<int>();
    EXPECT_EQ(bandTop + band[3].get<int>(), canvasHeight);
    EXPECT_LE(detail["stimulus"][1].get<int>() + detail["stimulus"][3].get<int>(), bandTop);
    if (detail.contains("plan")) { EXPECT_LE(detail["plan"][1].get<int>() + detail["plan"][3].get<int>(), bandTop); }
    if (detail.contains("buttons"))
      for (const auto& [label, centre] : detail["buttons"].items()) { EXPECT_GT(centre[1].get<double>(), bandTop) << label; }
    ++onsetCount;
  }
  EXPECT_EQ(onsetCount, 3);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM events WHERE kind IN ('pause', 'resume')"), 2);
}

}  // namespace

TEST(WindowRun, ParticipantAnswersByKeyboardAndClicksUnderXvfb) {
  if (!haveTool("Xvfb") || !haveTool("xdotool")) GTEST_SKIP() << "needs Xvfb and xdotool (scripts/setup.sh installs both)";
  WindowSession session("window_run", 300, "window.toml", "P'01; DROP TABLE trials");
  const std::string& db = session.db;
  const std::string& window = session.window;
  ASSERT_FALSE(window.empty()) << session.err();
  const auto trials = waitForTrials(db);
  ASSERT_EQ(trials.size(), 3u) << session.err();
  pause(500);

  press(session, "space", 400);  // welcome
  press(session, "space", 400);  // task instructions
  const std::string layer = trials[0].question["truth"].dump();
  press(session, "Escape", 500);  // pause: the paused time is left out of the RT
  press(session, "space", 200);   // resume
  session.xdo("type --window " + window + " " + layer);
  press(session, "Return", 400);
  press(session, "space", 400);  // next task's instructions
  const nlohmann::json boundaryLayout = waitForOnsetLayout(db, 1);
  ASSERT_TRUE(boundaryLayout.contains("labels")) << boundaryLayout;
  const std::vector<std::string> expected = clickBoundaryLabels(session, trials[1], boundaryLayout);
  press(session, "space", 400);  // next task's instructions
  const auto truth = trials[2].question["truth"];
  const nlohmann::json planLayout = waitForOnsetLayout(db, 2);
  ASSERT_TRUE(planLayout.contains("plan")) << planLayout;
  clickFloorTarget(session, truth, planLayout);
  press(session, "4", 400);       // questionnaire
  press(session, "Return", 400);  // confirm the answers
  session.xdo("key --window " + window + " space");  // debrief
  const int code = session.finish();
  const std::string out = session.out();
  ASSERT_EQ(code, 0) << out << session.err();
  EXPECT_NE(out.find("session finished: 3 of 3 trials answered"), std::string::npos) << out;
  std::printf("%s", out.substr(out.find("timing:")).c_str());
  expectResponses(db, layer, expected, truth);
  expectSessionRecords(db);
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

// The gauge figure in the window: a drag from its centre points the stick at the pointer, the arrow
// keys turn it, Enter is Done; the stored direction is the one the last logged orientation gives.
TEST(WindowRun, ParticipantTurnsAGaugeByDragAndArrowKeysUnderXvfb) {
  if (!haveTool("Xvfb") || !haveTool("xdotool")) GTEST_SKIP() << "needs Xvfb and xdotool (scripts/setup.sh installs both)";
  WindowSession session("window_gauge", 500, "gauge_window.toml", "G1");
  const auto xdo = [&](const std::string& args) { return session.xdo(args); };
  ASSERT_FALSE(session.window.empty()) << session.err();
  const auto trials = waitForTrials(session.db);
  ASSERT_EQ(trials.size(), 1u) << session.err();
  pause(500);
  xdo("key --window " + session.window + " space");  // welcome
  pause(400);
  xdo("key --window " + session.window + " space");  // task instructions
  const nlohmann::json& q = trials[0].question;
  const nlohmann::json layout = waitForOnsetLayout(session.db, 0);  // where the window drew the gauge
  ASSERT_TRUE(layout.contains("gauge")) << layout;
  const glm::dvec2 centre(layout["gauge"]["centre"][0].get<double>(), layout["gauge"]["centre"][1].get<double>());
  pause(600);
  const std::string w = " --window " + session.window + " ";
  xdo("key" + w + "space");  // a stray Space in the trial: blanks are no typed answer, Enter still gives the gauge
  pause(200);
  xdo("mousemove" + w + std::to_string(int(centre.x) - 1) + " " + std::to_string(int(centre.y)));
  xdo("mousedown" + w + "1");
  for (int i = 1; i <= 4; ++i) {
    xdo("mousemove" + w + std::to_string(int(centre.x) + 6 * i) + " " + std::to_string(int(centre.y) - 6 * i));
    pause(150);
  }
  xdo("mouseup" + w + "1");
  pause(300);
  xdo("key" + w + "Up");
  pause(300);
  xdo("key" + w + "Return");
  pause(500);
  xdo("key" + w + "space");  // goodbye
  ASSERT_EQ(session.finish(), 0) << session.out() << session.err();

  Database d(session.db, false);
  auto gauges = d.prepare("SELECT detail FROM events WHERE kind = 'camera' ORDER BY id");
  std::string last;
  int turns = 0;
  while (gauges.step()) last = gauges.text(0), ++turns;
  ASSERT_GE(turns, 2) << "drags and an arrow key";
  double slant = 0, tilt = 0;
  ASSERT_EQ(std::sscanf(last.c_str(), "gauge slant=%lf tilt=%lf", &slant, &tilt), 2) << last;
  EXPECT_GT(slant, 10.0);  // dragged away from the centre, then 2° more
  EXPECT_GT(tilt, 0.0);
  EXPECT_LT(tilt, 90.0);  // up and to the right
  auto response = d.prepare("SELECT raw_answer, error FROM responses");
  ASSERT_TRUE(response.step());
  double n[3];
  ASSERT_EQ(std::sscanf(response.text(0).c_str(), "%lf,%lf,%lf", &n[0], &n[1], &n[2]), 3) << response.text(0);
  const auto& f = q["directions"];
  const double s = slant * M_PI / 180.0, t = tilt * M_PI / 180.0;
  for (int i = 0; i < 3; ++i) {
    const double expected = std::sin(s) * std::cos(t) * f["right"][i].get<double>() + std::sin(s) * std::sin(t) * f["up"][i].get<double>() +
                            std::cos(s) * f["toward-eye"][i].get<double>();
    EXPECT_NEAR(n[i], expected, 1e-4) << "component " << i << " of " << response.text(0);  // the log has 2 decimals of a degree
  }
  EXPECT_GE(response.real(1), 0.0);
}
