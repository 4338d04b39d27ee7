// `tlab replay` end to end: a participant orbits a live scene in a real window under Xvfb (drags,
// the cursor moving the dynamic lens, arrow keys), every frame shown is logged, and the replay of
// that trial renders every frame again with the logged hash: "N of N frames identical" (N > 1,
// frames that differ), PNG frames whose pixels hash to the logged values, a video from which
// ffmpeg extracts a frame (kept for looking at in build/test-screenshots/replay/), and the HTML
// page. A copy of the database with one hash changed names that frame and exits 1. Bad input —
// a missing database, an unknown participant or trial, a trial that is not interactive or has no
// frames — is one line and exit 1.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/png_file.hpp"
#include "study/run/canvas.hpp"
#include "study/run/frame_log.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/study/window_session.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;
namespace fs = std::filesystem;

namespace {

// The logged frames of the database's only interactive trial, in the order stored.
std::vector<tlab::study::LiveFrame> loggedFrames(const std::string& db) {
  tlab::study::Database d(db, false);
  auto s = d.prepare("SELECT detail FROM events WHERE kind = 'frame' ORDER BY id");
  std::vector<tlab::study::LiveFrame> frames;
  while (s.step()) frames.push_back(tlab::study::parseFrameJson(s.text(0)));
  return frames;
}

// The participant at the window: the welcome and instructions, a drag across the stimulus with
// the cursor (the lens follows it), an arrow key, the count typed and Enter, the goodbye.
void orbitAndAnswer(WindowSession& session, const std::string& count) {
  const std::string w = " --window " + session.window + " ";
  press(session, "space", 400);  // welcome
  press(session, "space", 600);  // task instructions
  session.xdo("mousemove" + w + "300 230");
  pause(300);
  session.xdo("mousedown" + w + "1");
  for (int i = 1; i <= 4; ++i) {
    session.xdo("mousemove" + w + std::to_string(300 + 12 * i) + " " + std::to_string(230 + 6 * i));
    pause(200);
  }
  session.xdo("mouseup" + w + "1");
  pause(300);
  session.xdo("mousemove" + w + "350 200");  // the lens follows the cursor
  pause(300);
  press(session, "Up", 300);
  session.xdo("type" + w + count);
  press(session, "Return", 500);
  session.xdo("key" + w + "space");  // goodbye
}

// build/test-screenshots/replay: what the test leaves for looking at.
fs::path screenshots() { return fs::path(kTlab).parent_path().parent_path() / "test-screenshots" / "replay"; }

// The `tlab ...` lines of the README block marked "replay-steps: tested".
std::vector<std::string> readmeSteps() {
  const std::string readme = readText(std::string(TLAB_SOURCE_DIR) + "/README.md");
  const auto marker = readme.find("<!-- replay-steps: tested -->");
  if (marker == std::string::npos) return {};
  const auto begin = readme.find("```sh\n", marker) + 6, end = readme.find("```\n", begin);
  std::istringstream block(readme.substr(begin, end - begin));
  std::vector<std::string> steps;
  for (std::string line; std::getline(block, line);)
    if (line.rfind("tlab ", 0) == 0) steps.push_back(line);
  return steps;
}

// A README step run as written in `folder`, with the session's database for live.db.
CommandResult runStep(const std::string& step, const std::string& db, const fs::path& folder) {
  std::string command = std::regex_replace(step, std::regex("^tlab "), quoted(kTlab) + " ");
  command = std::regex_replace(command, std::regex(" live\\.db "), " " + quoted(db) + " ");
  return runCommand("cd " + quoted(folder.string()) + " && " + command);
}

CommandResult replay(const std::string& db, const std::string& participant, const std::string& trial, const std::string& more = "") {
  return runCommand(commandLine({kTlab, "replay", db, "--participant", participant, "--trial", trial}) + " " + more);
}

// The pixels of a PNG file hashed as a logged frame is.
std::string pngPixelsSha256(const fs::path& png) {
  const auto image = tlab::core::readPngFile(png.string());
  return image ? tlab::study::framePixelsSha256(tlab::study::Canvas(*image)) : "unreadable " + png.string();
}

void expectFramesHashToTheLog(const fs::path& folder, const std::vector<tlab::study::LiveFrame>& logged) {
  std::size_t pngs = 0;
  for (const auto& entry : fs::directory_iterator(folder)) pngs += entry.path().extension() == ".png";
  EXPECT_EQ(pngs, logged.size());
  for (std::size_t i = 0; i < logged.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%06zu.png", i);
    EXPECT_EQ(pngPixelsSha256(folder / name), logged[i].sha256) << name;
  }
}

// A frame of the video, extracted by ffmpeg and kept for looking at; its size and that it is no blank.
void expectVideoFrame(const fs::path& video, const fs::path& still) {
  fs::create_directories(still.parent_path());
  const auto extracted = runCommand(commandLine({"ffmpeg", "-nostdin", "-v", "error", "-y", "-i", video.string(), "-vf", "select=eq(n\\,2)",
                                                 "-frames:v", "1", still.string()}));
  ASSERT_EQ(extracted.exitCode, 0) << extracted.err;
  const auto image = tlab::core::readPngFile(still.string());
  ASSERT_TRUE(image);
  EXPECT_EQ(image->width, 160);
  EXPECT_EQ(image->height, 160);
  std::set<int> greys;
  for (const auto& p : image->pixels) greys.insert(int(255 * (p.r + p.g + p.b) / 3));
  EXPECT_GT(greys.size(), 20u) << "the video frame shows the scene, not a blank";
}

}  // namespace

TEST(ReplayWindow, OrbitTrialReplaysIdenticallyAsFramesVideoAndPageAndATamperedHashIsNamed) {
  if (!haveTool("Xvfb") || !haveTool("xdotool") || !haveTool("ffmpeg"))
    GTEST_SKIP() << "needs Xvfb, xdotool and ffmpeg (scripts/setup.sh installs them)";
  const auto steps = readmeSteps();
  ASSERT_EQ(steps.size(), 4u);
  ASSERT_EQ(steps[0], "tlab run tests/study/data/live_replay.toml --participant R1 --db live.db --size 640x480") << "what the session runs";
  WindowSession session("replay_window", 600, "live_replay.toml", "R1");
  ASSERT_FALSE(session.window.empty()) << session.err();
  const auto trials = waitForTrials(session.db);
  ASSERT_EQ(trials.size(), 1u) << session.err();
  pause(500);
  orbitAndAnswer(session, trials[0].question["truth"].dump());
  ASSERT_EQ(session.finish(), 0) << session.out() << session.err();

  const auto logged = loggedFrames(session.db);
  ASSERT_GT(logged.size(), 3u) << "start, drags, the lens and the arrow key";
  EXPECT_EQ(logged.front().input, "start");
  std::set<std::string> hashes;
  bool lens = false;
  for (std::size_t i = 0; i < logged.size(); ++i) {
    EXPECT_EQ(logged[i].index, int(i)) << "every picture rendered is shown and logged";
    if (i > 0) { EXPECT_GE(logged[i].shownNs, logged[i - 1].shownNs); }
    hashes.insert(logged[i].sha256);
    lens = lens || logged[i].lens.has_value();
  }
  EXPECT_GT(hashes.size(), 2u) << "the frames differ from each other";
  EXPECT_TRUE(lens) << "a frame with the lens where the cursor was";

  // The README's replay steps, as written, in a folder of their own.
  const fs::path out = session.dir / "replay";
  fs::create_directories(out);
  const std::string n = std::to_string(logged.size());
  const auto check = runStep(steps[1], session.db, out);
  ASSERT_EQ(check.exitCode, 0) << check.out << check.err;
  EXPECT_NE(check.out.find("\n" + n + " of " + n + " frames identical\n"), std::string::npos) << check.out;
  const auto r = runStep(steps[2], session.db, out);
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find(n + " of " + n + " frames identical"), std::string::npos) << r.out;
  expectFramesHashToTheLog(out / "frames", logged);
  expectFramesHashToTheLog(out / "replay-frames", logged);
  expectVideoFrame(out / "replay.webm", screenshots() / "video-frame-2.png");
  const std::string page = readText((out / "replay.html").string());
  EXPECT_NE(page.find(n + " of " + n + " frames identical"), std::string::npos);
  EXPECT_NE(page.find("replay-frames/frame-000000.png"), std::string::npos);
  EXPECT_NE(page.find("“" + trials[0].question["truth"].dump() + "”, correct"), std::string::npos) << "the answer given";
  fs::copy_file(out / "replay.html", screenshots() / "replay.html", fs::copy_options::overwrite_existing);
  fs::copy(out / "replay-frames", screenshots() / "replay-frames",
           fs::copy_options::overwrite_existing | fs::copy_options::recursive);

  // The study's report, as the README's last step writes it, names the replay of the trial and
  // links the page it rendered, with its check.
  const auto report = runStep(steps[3], session.db, out);
  ASSERT_EQ(report.exitCode, 0) << report.out << report.err;
  EXPECT_NE(report.out.find("wrote 1 replay page to report-replays: " + n + " of " + n + " frames identical"), std::string::npos) << report.out;
  const std::string reportPage = readText((out / "report.html").string());
  EXPECT_NE(reportPage.find("Interactive trials with their live frames logged"), std::string::npos);
  EXPECT_NE(reportPage.find("--participant 'R1' --trial 1 --html 'replay-R1-trial1.html'"), std::string::npos);
  EXPECT_NE(reportPage.find("<a href=\"report-replays/replay-R1-trial1.html\">" + n + " of " + n + " frames identical</a>"), std::string::npos);
  expectFramesHashToTheLog(out / "report-replays" / "replay-R1-trial1-frames", logged);

  // One hash changed in a copy: that frame is named, with why, and the replay exits 1.
  const std::string tampered = (session.dir / "tampered.db").string();
  fs::copy_file(session.db, tampered);
  const std::size_t k = logged.size() / 2;
  tlab::study::LiveFrame changed = logged[k];
  changed.sha256 = std::string(64, 'a');
  {
    tlab::study::Database d(tampered, true);
    auto s = d.prepare("UPDATE events SET detail = ?1 WHERE id = (SELECT id FROM events WHERE kind = 'frame' ORDER BY id LIMIT 1 OFFSET " +
                       std::to_string(k) + ")");
    s.bind(1, tlab::study::frameJson(changed));
    s.step();
  }
  const auto t = replay(tampered, "R1", "1");
  EXPECT_EQ(t.exitCode, 1);
  EXPECT_NE(t.out.find("frame " + std::to_string(k) + " (session 1, index " + std::to_string(k) + ","), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("logged aaaaaaaaaaaaaaaa"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("same GL"), std::string::npos) << "the GL and version are the same: the log was changed; " << t.out;
  EXPECT_NE(t.out.find(std::to_string(logged.size() - 1) + " of " + n + " frames identical"), std::string::npos) << t.out;
  EXPECT_EQ(t.err, "tlab: error: 1 of " + n + " frames differ from the log (listed above)\n");
}

TEST(ReplayWindow, BadInputIsOneLineAndExitOne) {
  const fs::path dir = freshDir("replay_bad_input");
  const std::string live = (dir / "live.db").string(), tiny = (dir / "tiny.db").string();
  ASSERT_EQ(runCommand(commandLine({kTlab, "simulate", studyData("live_replay.toml"), "--db", live})).exitCode, 0);
  ASSERT_EQ(runCommand(commandLine({kTlab, "simulate", studyData("tiny.toml"), "--participants", "1", "--db", tiny})).exitCode, 0);
  const auto bytes = readText(live);
  const struct {
    std::string db, participant, trial, message;
  } cases[] = {
      {(dir / "missing.db").string(), "sim-001", "1", "missing.db: no such database"},
      {live, "nobody", "1", "no participant 'nobody' in experiment 'live-replay'"},
      {live, "sim-001", "9", "participant 'sim-001' has no trial 9 (trials 1 to 1)"},
      {live, "sim-001", "1", "trial 1 of participant 'sim-001' (task count) has no live frames logged"},
      {tiny, "sim-001", "2", "(task layer) is not interactive"},
  };
  for (const auto& c : cases) {
    const auto r = replay(c.db, c.participant, c.trial);
    EXPECT_EQ(r.exitCode, 1) << c.message;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_EQ(readText(live), bytes) << "a replay only reads the database";
  EXPECT_FALSE(fs::exists(dir / "missing.db"));
}
