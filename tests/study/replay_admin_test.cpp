// The admin page of `tlab serve` lists, per participant, the trials whose live frames were logged
// with the `tlab replay` command of each (the admin token required, as for the whole page): a
// participant answers a trial of the tiny served study, a frame event is stored for it as a front
// end stores one, and the status and the page show its replay. A live trial orbited over HTTP is
// replayed from the admin page's link (rendered on demand by a child process, served under an
// unguessable key) and from the report's (`tlab report --replays`), every frame identical.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <thread>

#include "core/png_file.hpp"
#include "tests/support/run_command.hpp"

#include "study/run/frame_log.hpp"
#include "study/store/sqlite_database.hpp"
#include "tests/study/serve_test_client.hpp"
#include "tests/study/served_study.hpp"
#include "tests/study/study_test_support.hpp"

namespace tlab::testing {
namespace {

// A frame event for the participant's first trial in their session, as the window stores one.
void storeFrame(const std::string& db, const std::string& participant) {
  study::LiveFrame f;
  f.input = "start";
  f.sha256 = std::string(64, 'b');
  study::Database d(db, false);
  auto s = d.prepare("INSERT INTO events (session, trial, t_ns, kind, detail) SELECT s.id, t.id, 1, 'frame', ?1 FROM sessions s "
                     "JOIN participants p ON p.id = s.participant JOIN trials t ON t.participant = p.id "
                     "WHERE p.participant = ?2 AND t.sequence = 1");
  s.bind(1, study::frameJson(f));
  s.bind(2, participant);
  s.step();
}

TEST(ReplayAdmin, ThePageListsTheReplayCommandOfEachTrialWithFrames) {
  const auto dir = freshDir("replay_admin");
  const std::string db = (dir / "study.db").string();
  ServedStudy server(studyData("serve_tiny.toml"), db, dir);
  PageClient page(server.port());
  const std::string admin = server.adminToken();
  const auto [status, token] = page.arrive("serve-tiny", "PROLIFIC_PID=p1&STUDY_ID=s1&SESSION_ID=x");
  ASSERT_EQ(status, 303);
  walk(page, token, page.api(token, "display", display()).body, 1);
  EXPECT_EQ(page.get("/admin/status.json?token=" + admin).body["replays"], nlohmann::json::array()) << "no frames yet";
  EXPECT_NE(page.raw("/admin?token=" + admin)->body.find("none yet"), std::string::npos);

  storeFrame(db, "p1");
  const nlohmann::json replays = page.get("/admin/status.json?token=" + admin).body["replays"];
  ASSERT_EQ(replays.size(), 1u) << replays.dump();
  EXPECT_EQ(replays[0]["participant"], "p1");
  EXPECT_EQ(replays[0]["trial"], 1);
  EXPECT_EQ(replays[0]["frames"], 1);
  const std::string command = "tlab replay '" + db + "' --participant 'p1' --trial 1 --html 'replay-p1-trial1.html'";
  EXPECT_EQ(replays[0]["command"], command);
  const auto html = page.raw("/admin?token=" + admin);
  ASSERT_EQ(html->status, 200);
  EXPECT_NE(html->body.find("<h2>Replays of interactive trials</h2>"), std::string::npos);
  EXPECT_NE(html->body.find("<code>" + command + "</code>"), std::string::npos) << html->body;
  EXPECT_EQ(page.raw("/admin/status.json?token=" + std::string(64, 'a'))->status, 403);
}

// The frames of a live trial as the page asks for them; their logged SHA-256s, in order.
std::vector<std::string> orbitAndAnswer(PageClient& page, int port, const std::string& token) {
  nlohmann::json screen = page.api(token, "display", display()).body;
  while (screen["kind"] != "trial" && screen["kind"] != "end") screen = page.api(token, "reply", continueReply(screen)).body;
  EXPECT_EQ(screen["kind"], "trial") << screen.dump();
  const int seq = screen["seq"];
  EXPECT_EQ(page.api(token, "reply", {{"seq", seq}, {"type", "onset"}, {"painted_ms", 10.5}}).status, 200);
  httplib::Client http("127.0.0.1", port);
  http.set_read_timeout(120, 0);
  std::vector<std::string> logged;
  for (const nlohmann::json& input : {nlohmann::json::object(), nlohmann::json{{"dx", 40}}, nlohmann::json{{"point", {0.3, 0.6}}}}) {
    const auto r = http.Post(("/api/" + token + "/view").c_str(), nlohmann::json{{"seq", seq}, {"input", input}}.dump(), "application/json");
    EXPECT_TRUE(r && r->status == 200) << (r ? r->body : "no reply");
    if (r) logged.push_back(r->get_header_value("X-Frame-Sha256"));
  }
  const Walk rest = walk(page, token, screen);
  EXPECT_EQ(rest.screens.back()["kind"], "end") << rest.screens.back().dump();
  return logged;
}

// "a&amp;b" as the browser reads the attribute.
std::string unescaped(std::string text) {
  for (std::size_t at = 0; (at = text.find("&amp;", at)) != std::string::npos; ++at) text.replace(at, 5, "&");
  return text;
}

TEST(ReplayAdmin, ALiveTrialIsReplayedFromTheAdminPageAndTheReportEveryFrameIdentical) {
  const auto dir = freshDir("replay_links");
  const std::string db = (dir / "study.db").string();
  ServedStudy server(studyData("live_replay.toml"), db, dir);
  PageClient page(server.port());
  const std::string admin = server.adminToken();
  const auto [status, token] = page.arrive("live-replay", "pid=p1");
  ASSERT_EQ(status, 303);
  const std::vector<std::string> logged = orbitAndAnswer(page, server.port(), token);
  ASSERT_EQ(logged.size(), 3u);

  // The admin page links the trial's replay; the link starts it and sends the browser to its key.
  const std::string adminPage = page.raw("/admin?token=" + admin)->body;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(adminPage, m, std::regex("href=\"(/admin/replay\\?token=[0-9a-f]{64}&amp;participant=p1&amp;trial=1)\"")))
      << adminPage;
  const std::string link = unescaped(m[1]);
  EXPECT_EQ(page.raw(link.substr(0, link.find('?')) + "?participant=p1&trial=1")->status, 403) << "the admin token is needed";
  EXPECT_EQ(page.raw("/admin/replay?token=" + admin + "&participant=p1&trial=2")->status, 404) << "no such live trial";
  const auto started = page.raw(link);
  ASSERT_EQ(started->status, 303);
  const std::string at = started->get_header_value("Location");
  ASSERT_TRUE(std::regex_match(at, std::regex("/admin/replays/[0-9a-f]{32}/"))) << at;
  EXPECT_EQ(page.raw(link)->get_header_value("Location"), at) << "asked again, the same replay";

  // Its address shows progress until the page is there (rendered by tlab replay at nice 19).
  std::string done;
  for (int i = 0; i < 600 && done.empty(); ++i) {
    const auto r = page.raw(at);
    ASSERT_TRUE(r->status == 200 || r->status == 303) << r->status << " " << r->body;
    if (r->status == 303) done = r->get_header_value("Location");
    else std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  ASSERT_EQ(done, "replay.html");
  const auto html = page.raw(at + "replay.html");
  ASSERT_EQ(html->status, 200);
  EXPECT_NE(html->body.find("3 of 3 frames identical"), std::string::npos) << html->body;
  EXPECT_NE(html->get_header_value("Content-Security-Policy").find("script-src 'unsafe-inline'"), std::string::npos);
  for (std::size_t i = 0; i < logged.size(); ++i) {
    const auto png = page.raw(at + "replay-frames/frame-00000" + std::to_string(i) + ".png");
    ASSERT_EQ(png->status, 200);
    const auto file = dir / "frame.png";
    std::ofstream(file, std::ios::binary) << png->body;
    const auto image = core::readPngFile(file.string());
    ASSERT_TRUE(image);
    EXPECT_EQ(study::framePixelsSha256(study::Canvas(*image)), logged[i]) << "frame " << i << " is the picture the participant saw";
  }
  for (const std::string& bad : {at + "replay.log", at + "replay-frames/../replay.html", at + "replay-frames/frame-000099.png",
                                 std::string("/admin/replays/") + std::string(32, '0') + "/replay.html"})
    EXPECT_EQ(page.raw(bad)->status, 404) << bad;

  // Stopped, the server leaves none of its replays behind.
  const std::string key = at.substr(15, 32);
  server.stop(SIGTERM);
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
    EXPECT_FALSE(std::filesystem::exists(entry.path() / key)) << entry.path();

  // The report renders the replay and links it with its check.
  const auto report = runCommand(commandLine({TLAB_EXE, "report", db, "-o", (dir / "report.html").string(), "--replays"}));
  ASSERT_EQ(report.exitCode, 0) << report.out << report.err;
  EXPECT_NE(report.out.find("wrote 1 replay page to " + (dir / "report-replays").string() + ": 3 of 3 frames identical"), std::string::npos)
      << report.out;
  EXPECT_NE(readText((dir / "report.html").string()).find("<a href=\"report-replays/replay-p1-trial1.html\">3 of 3 frames identical</a>"),
            std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "report-replays" / "replay-p1-trial1-frames" / "frame-000002.png"));
  std::ofstream(dir / "data.csv") << "x\n1\n2\n";
  const auto csv = runCommand(commandLine({TLAB_EXE, "report", (dir / "data.csv").string(), "--dv", "x", "-o", (dir / "csv.html").string(), "--replays"}));
  EXPECT_EQ(csv.exitCode, 1);
  EXPECT_NE(csv.err.find("--replays renders the interactive trials of a study database"), std::string::npos) << csv.err;
}

}  // namespace
}  // namespace tlab::testing

