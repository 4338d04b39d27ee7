// The participant's session flow (welcome → consent → information → instructions → training with
// feedback → "training is over" → trials with breaks → questionnaires → debrief), walked by
// simulated observers and, under Xvfb, by `tlab run` in a real window: declined by a participant
// typing on the keyboard (xdotool), completed by the autopilot, killed during a break and resumed,
// and the feedback screen checked in a screenshot.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <chrono>
#include <set>
#include <thread>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include <nlohmann/json.hpp>

#include "study/store/sqlite_database.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;
using tlab::study::Database;

namespace {

const std::string kTlab = TLAB_EXE;
constexpr int kTrials = 6;  // flow.toml: 2 training questions + 2 blocks × 2 test questions

bool haveTool(const std::string& name) { return runCommand("command -v " + name).exitCode == 0; }
void pause(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

// An Xvfb display of its own for the life of the object. Each test takes its own hundred display
// numbers (window_cli_test 90-189, window_run_test 300-499, these 900-1399), so tests running in
// parallel never share a server.
struct Display {
  std::string name, env;
  pid_t xvfb = -1;
  explicit Display(const std::filesystem::path& dir, int base) {
    name = ":" + std::to_string(base + ::getpid() % 100);
    xvfb = spawnProcess({"Xvfb", name, "-screen", "0", "800x600x24"}, (dir / "xvfb.out").string(), (dir / "xvfb.err").string());
    pause(800);
    env = "DISPLAY=" + name;
  }
  ~Display() {
    ::kill(xvfb, SIGTERM);
    waitProcess(xvfb);
  }
};

std::vector<std::string> runArgs(const std::string& db, const std::string& participant, bool autopilot) {
  std::vector<std::string> args = {kTlab, "run", studyData("flow.toml"), "--participant", participant, "--db", db, "--size", "640x480"};
  if (autopilot) args.insert(args.end(), {"--autopilot", "--autopilot-pace", "0.01"});
  return args;
}

// Waits until the process stops itself at its fault point (true) or ends (false).
bool stoppedAtFaultPoint(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, WUNTRACED);
  return WIFSTOPPED(status);
}

}  // namespace

TEST(SessionFlow, SimulatedObserversWalkEveryStep) {
  const auto dir = freshDir("flow_simulated");
  const std::string db = (dir / "study.db").string();
  const auto r = runCommand(kTlab + " simulate " + studyData("flow.toml") + " --db " + quoted(db));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM consent WHERE decision = 'accepted'"), 2);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM participant_info"), 2 * 4);  // age, gender, vision, handedness
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM questionnaire_answers"), 2 * 4);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM questionnaire_answers WHERE item = 'minutes' AND value BETWEEN 0 AND 120"), 2);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM events WHERE kind = 'break'"), 2);  // after test trial 2 of 4
  // Training never shows a stimulus of a test trial.
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM trials a JOIN trials b ON a.participant = b.participant AND a.stimulus_sha256 = "
                      "b.stimulus_sha256 WHERE a.phase = 'training' AND b.phase = 'test'"),
            0);
  ASSERT_EQ(runCommand(kTlab + " export " + quoted(db) + " --csv " + quoted((dir / "csv").string())).exitCode, 0);
  const auto info = parseCsv(readText((dir / "csv" / "participant_info.csv").string()));
  ASSERT_EQ(info.size(), 1u + 8);
  EXPECT_EQ(info[0], (std::vector<std::string>{"experiment", "participant", "field", "value", "number", "session", "recorded_at"}));
  const auto consent = parseCsv(readText((dir / "csv" / "consent.csv").string()));
  ASSERT_EQ(consent.size(), 1u + 2);
  EXPECT_EQ(consent[1][2], "accepted");
  ASSERT_EQ(runCommand(kTlab + " report " + quoted(db) + " -o " + quoted((dir / "report.html").string())).exitCode, 0);
  const std::string html = readText((dir / "report.html").string());
  for (const char* part : {"Participant information", "Which hand do you write with?", "Questionnaire 'post' (end): numbers", "free text",
                           "Timing per session"})
    EXPECT_NE(html.find(part), std::string::npos) << part;
}

TEST(SessionFlowWindow, DeclinedConsentStoresOnlyTheDecision) {
  if (!haveTool("Xvfb") || !haveTool("xdotool")) GTEST_SKIP() << "needs Xvfb and xdotool (scripts/setup.sh installs both)";
  const auto dir = freshDir("flow_decline");
  const std::string db = (dir / "study.db").string();
  Display display(dir, 900);
  const pid_t tlab = spawnProcess(runArgs(db, "P-decline", false), (dir / "run.out").string(), (dir / "run.err").string(), {display.env});
  const auto found = runCommand(display.env + " timeout 60 xdotool search --sync --name 'tlab run' | head -1");
  const std::string window = found.out.substr(0, found.out.find('\n'));
  ASSERT_FALSE(window.empty()) << readText((dir / "run.err").string());
  // A screen discards the keys pressed before it was shown, and under load a screen can take
  // seconds to appear, so fixed pauses between keys could lose one and leave tlab waiting for ever
  // (seen under the sanitizers). Space (welcome, then "you chose not to take part") and 2 (decline)
  // are pressed in turn until tlab ends: each screen takes only its own key, so the order of the
  // screens is the only one the keys can walk, at any speed.
  int status = 0;
  bool ended = false;
  for (int round = 0; round < 240 && !ended; ++round) {
    runCommand(display.env + " xdotool key --window " + window + (round % 2 == 0 ? " space" : " 2"));
    pause(250);
    ended = ::waitpid(tlab, &status, WNOHANG) == tlab;
  }
  if (!ended) ::kill(tlab, SIGKILL), waitProcess(tlab);
  ASSERT_TRUE(ended) << "tlab run did not end within a minute of keys: " << readText((dir / "run.err").string());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << readText((dir / "run.err").string());
  EXPECT_NE(readText((dir / "run.out").string()).find("declined"), std::string::npos);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM participants WHERE status = 'declined' AND slot = -1"), 1);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM consent WHERE decision = 'declined'"), 1);
  for (const char* table : {"assignments", "sessions", "trials", "responses", "participant_info"})
    EXPECT_EQ(queryCount(db, std::string("SELECT count(*) FROM ") + table), 0) << table;
  // The same person is refused later with one line; the slot went to nobody.
  const auto again = runCommand(kTlab + " simulate " + studyData("flow.toml") + " --participants 1 --db " + quoted(db));
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_EQ(queryCount(db, "SELECT min(slot) FROM assignments"), 0);
}

namespace {

// What the keyboard session stored: every answer correct, the information and questionnaire
// answers as typed, the feedback and the break, and the choice buttons below the question.
void expectKeyboardSessionStored(const std::string& db) {
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM responses WHERE correct = 1"), kTrials);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM participant_info WHERE (field = 'age' AND value = '34') OR "
                      "(field = 'gender' AND value = 'female') OR (field = 'handedness' AND value = 'right')"),
            3);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM questionnaire_answers WHERE (item = 'ease' AND value = 4) OR (item = 'strategy' AND "
                      "answer = 'the shading') OR (item = 'minutes' AND value = 15) OR (item = 'comments' AND answer = 'none')"),
            4);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM events WHERE kind = 'feedback' AND detail LIKE '%\"correct\":true%'"), 2);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM events WHERE kind = 'break-end'"), 1);
  // The choice buttons sit below the question and its hint (the question text at y = 90), not over them.
  Database d(db, false);
  auto form = d.prepare("SELECT detail FROM events WHERE kind = 'form-item' AND detail LIKE '%\"field\":\"gender\"%'");
  ASSERT_TRUE(form.step());
  const auto buttons = nlohmann::json::parse(form.text(0))["buttons"];
  ASSERT_EQ(buttons.size(), 4u);
  for (const auto& [label, centre] : buttons.items()) EXPECT_GT(centre[1].get<int>(), 150) << label;
}

}  // namespace

// A participant at the keyboard (xdotool, through X and GLFW's callbacks): agrees, fills in the
// information, trains with feedback, takes the break, answers every questionnaire item kind,
// confirms and reads the completion code.
TEST(SessionFlowWindow, ParticipantAcceptsAndFinishesAtTheKeyboard) {
  if (!haveTool("Xvfb") || !haveTool("xdotool")) GTEST_SKIP() << "needs Xvfb and xdotool (scripts/setup.sh installs both)";
  const auto dir = freshDir("flow_keyboard");
  const std::string db = (dir / "study.db").string();
  Display display(dir, 1300);
  const pid_t tlab = spawnProcess(runArgs(db, "P-keys", false), (dir / "run.out").string(), (dir / "run.err").string(), {display.env});
  const auto found = runCommand(display.env + " timeout 60 xdotool search --sync --name 'tlab run' | head -1");
  const std::string window = found.out.substr(0, found.out.find('\n'));
  ASSERT_FALSE(window.empty()) << readText((dir / "run.err").string());
  pause(1500);
  const auto key = [&](const std::string& k) {
    runCommand(display.env + " xdotool key --window " + window + " " + k);
    pause(350);
  };
  const auto type = [&](const std::string& text) {
    runCommand(display.env + " xdotool type --window " + window + " " + text);
    key("Return");
  };
  key("space");  // welcome
  key("1");      // consent: agree
  type("34");    // age
  key("1");      // gender: female
  key("2");      // vision: corrected
  key("2");      // handedness: right
  key("Return");  // confirm the information
  key("space");   // training instructions
  // The plan is stored once the participant agreed: the right answers are read from it.
  std::vector<std::string> truths;
  {
    Database d(db, false);
    auto s = d.prepare("SELECT truth_json FROM trials ORDER BY sequence");
    while (s.step()) truths.push_back(s.text(0));
  }
  ASSERT_EQ(truths.size(), std::size_t(kTrials));
  type(truths[0]);
  key("space");  // feedback
  type(truths[1]);
  key("space");  // feedback
  key("space");  // training is over
  type(truths[2]);
  type(truths[3]);
  pause(1200);   // the break's minimum second
  key("space");  // continue after the break
  type(truths[4]);
  type(truths[5]);
  key("4");          // ease (likert 1-5)
  key("2");          // strategy: the shading
  type("15");        // minutes
  type("none");      // comments
  key("Return");     // confirm the answers
  key("space");      // debrief with the completion code
  ASSERT_EQ(waitProcess(tlab), 0) << readText((dir / "run.err").string());
  EXPECT_NE(readText((dir / "run.out").string()).find("session finished: 6 of 6 trials answered"), std::string::npos);
  expectKeyboardSessionStored(db);
}

TEST(SessionFlowWindow, AutopilotWalksTheWholeSessionAndTimingIsRecorded) {
  if (!haveTool("Xvfb")) GTEST_SKIP() << "needs Xvfb (scripts/setup.sh installs it)";
  const auto dir = freshDir("flow_autopilot");
  const std::string db = (dir / "study.db").string();
  Display display(dir, 1000);
  const auto r = runCommand(display.env + " " + commandLine(runArgs(db, "P-auto", true)));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("session finished: 6 of 6 trials answered"), std::string::npos) << r.out;
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM participants WHERE status = 'finished'"), 1);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM sessions WHERE mode = 'autopilot' AND display_json LIKE '%gl_renderer%'"), 1);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM responses WHERE onset_to_swap_ms > 0 AND onset_frame_ms > 0 AND late_frames >= 0"), kTrials);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM events WHERE kind = 'feedback'"), 2);  // both training questions
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM events WHERE kind IN ('break', 'break-end')"), 2);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM participant_info"), 4);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM questionnaire_answers"), 4);
  const auto timing = runCommand(kTlab + " timing " + quoted(db));
  ASSERT_EQ(timing.exitCode, 0) << timing.err;
  EXPECT_NE(timing.out.find("llvmpipe"), std::string::npos) << timing.out;
  EXPECT_NE(timing.out.find("Timing per trial"), std::string::npos) << timing.out;
}

TEST(SessionFlowWindow, KilledDuringABreakResumesAfterIt) {
  if (!haveTool("Xvfb")) GTEST_SKIP() << "needs Xvfb (scripts/setup.sh installs it)";
  const auto dir = freshDir("flow_break_kill");
  const std::string db = (dir / "study.db").string();
  Display display(dir, 1100);
  const pid_t first = spawnProcess(runArgs(db, "P-break", true), (dir / "a.out").string(), (dir / "a.err").string(),
                                   {display.env, "TLAB_STOP_AT=break:1"});
  ASSERT_TRUE(stoppedAtFaultPoint(first)) << readText((dir / "a.err").string());
  ::kill(first, SIGKILL);
  waitProcess(first);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM responses"), 4);  // 2 training + 2 test, then the break
  auto args = runArgs(db, "P-break", true);
  args.push_back("--resume");
  const auto resumed = runCommand(display.env + " " + commandLine(args));
  ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("2 of 6 trials answered in this run (4 before)"), std::string::npos) << resumed.out;
  // The resumed session continued after the break: its first stimulus was trial 5, shown once.
  EXPECT_EQ(queryCount(db, "SELECT min(t.sequence) FROM events e JOIN trials t ON t.id = e.trial WHERE e.kind = 'onset' AND e.session = 2"), 5);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM events WHERE kind = 'onset'"), kTrials);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM sessions WHERE end_reason = 'interrupted' AND resumed_by = 2"), 1);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM participants WHERE status = 'finished'"), 1);
}

TEST(SessionFlowWindow, TrainingFeedbackIsVisibleInAScreenshot) {
  if (!haveTool("Xvfb") || !haveTool("import")) GTEST_SKIP() << "needs Xvfb and ImageMagick's import (scripts/setup.sh installs both)";
  const auto dir = freshDir("flow_feedback_screenshot");
  const std::string db = (dir / "study.db").string();
  Display display(dir, 1200);
  const pid_t p = spawnProcess(runArgs(db, "P-feedback", true), (dir / "run.out").string(), (dir / "run.err").string(),
                               {display.env, "TLAB_STOP_AT=feedback:1"});
  ASSERT_TRUE(stoppedAtFaultPoint(p)) << readText((dir / "run.err").string());
  const std::string shot = (dir / "feedback.png").string();
  const auto taken = runCommand(display.env + " import -window root " + quoted(shot));
  ::kill(p, SIGKILL);
  waitProcess(p);
  ASSERT_EQ(taken.exitCode, 0) << taken.err;
  int w = 0, h = 0, n = 0;
  unsigned char* pixels = stbi_load(shot.c_str(), &w, &h, &n, 3);
  ASSERT_NE(pixels, nullptr) << shot;
  // "Correct." in green or "Not correct." in red, in the header band at the top of the window.
  int coloured = 0;
  for (int y = 0; y < 60 && y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* px = pixels + 3 * (std::size_t(y) * w + x);
      const bool green = std::abs(px[0] - 20) < 30 && std::abs(px[1] - 140) < 30 && std::abs(px[2] - 60) < 30;
      const bool red = std::abs(px[0] - 190) < 30 && std::abs(px[1] - 30) < 30 && std::abs(px[2] - 30) < 30;
      coloured += green || red;
    }
  stbi_image_free(pixels);
  EXPECT_GT(coloured, 40) << "no feedback text in " << shot;
  const auto events = queryCount(db, "SELECT count(*) FROM events WHERE kind = 'feedback'");
  EXPECT_EQ(events, 0);  // killed on the feedback screen: its event was not yet stored
}
