// tlab serve end to end, as a participant's page and as an attacker would use it: the JSON API
// walked through a whole session, what the page never gets (the ground truth), what one token can
// reach, hostile requests, time-outs with back-filled slots, the admin page, and a restart.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <thread>

#include "study/design/participant_texts.hpp"
#include "tests/study/serve_test_client.hpp"
#include "tests/study/served_study.hpp"

namespace tlab::testing {
namespace {

using nlohmann::json;

const std::string kStudy = "serve-tiny";

class Serve : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = freshDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    db_ = (dir_ / "study.db").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string arrive(PageClient& page, const std::string& pid) {
    const auto [status, token] = page.arrive(kStudy, "PROLIFIC_PID=" + pid + "&STUDY_ID=s1&SESSION_ID=x" + pid);
    EXPECT_EQ(status, 303);
    EXPECT_EQ(token.size(), 64u);
    return token;
  }

  std::vector<std::vector<std::string>> exported(const std::string& table) { return exportedTable(db_, dir_, table); }

  std::filesystem::path dir_;
  std::string db_;
};

TEST_F(Serve, AParticipantWalksTheWholeSessionAndEveryAnswerIsStoredOnce) {
  ServedStudy server(studyData("serve_tiny.toml"), db_, dir_);
  PageClient page(server.port());
  const std::string token = arrive(page, "p1");
  const Reply first = page.api(token, "display", display());
  ASSERT_EQ(first.status, 200) << first.body.dump();
  const Walk w = walk(page, token, first.body);
  ASSERT_EQ(w.screens.back()["kind"], "end") << w.screens.back().dump();
  EXPECT_EQ(w.screens.back()["completion_code"], "C0DE42");
  EXPECT_EQ(w.screens.back()["completion_url"], "https://app.prolific.com/submissions/complete?cc=C0DE42");
  std::set<std::string> kinds;
  for (const auto& s : w.screens) kinds.insert(s["kind"].get<std::string>());
  for (const char* k : {"message", "consent", "trial", "feedback", "form", "end"}) EXPECT_TRUE(kinds.count(k)) << k;
  server.stop(SIGTERM);

  const auto trials = exported("trials");
  ASSERT_EQ(trials.size(), 1u + w.answered);
  const std::size_t answered = column(trials, "answered"), rt = column(trials, "rt_seconds"), raw = column(trials, "raw_answer");
  for (std::size_t i = 1; i < trials.size(); ++i) {
    EXPECT_EQ(trials[i][answered], "1");
    EXPECT_EQ(trials[i][rt], "0.84999999999999998");  // the browser's RT, as sent
    EXPECT_EQ(trials[i][raw], std::to_string(1 + (i - 1) % 2));
  }
  const auto sessions = exported("sessions");
  ASSERT_EQ(sessions.size(), 2u);
  EXPECT_EQ(sessions[1][column(sessions, "mode")], "browser");
  EXPECT_EQ(sessions[1][column(sessions, "status")], "finished");
  const json shown = json::parse(sessions[1][column(sessions, "display")]);
  EXPECT_EQ(shown["browser"]["screen_width"], 1920);
  EXPECT_FALSE(shown["gl_renderer"].get<std::string>().empty());  // the renderer that made the stimuli
  const auto events = exported("events");
  bool arrival = false;
  for (const auto& e : events)
    if (e[column(events, "kind")] == "arrival") arrival = e[column(events, "detail")].find("\"STUDY_ID\":\"s1\"") != std::string::npos;
  EXPECT_TRUE(arrival) << "the study and session parameters of the link are stored";
  int times = 0;
  for (const auto& e : events)
    times += e[column(events, "kind")] == "answer-times" && e[column(events, "detail")] == R"({"input_ms":860.5,"painted_ms":10.5,"rt_ms":850.0})";
  EXPECT_EQ(times, w.answered) << "both ends of every browser RT are stored";
  EXPECT_EQ(exported("questionnaires").size(), 2u);
  EXPECT_EQ(exported("consent").size(), 2u);
}

TEST_F(Serve, ThePageNeverGetsTheGroundTruth) {
  ServedStudy server(studyData("serve_tiny.toml"), db_, dir_);
  PageClient page(server.port());
  const std::string token = arrive(page, "p1");
  const Walk w = walk(page, token, page.api(token, "display", display()).body);
  const std::set<std::string> trialKeys = {"kind", "seq", "phase", "index", "total", "question", "answer_kind", "format", "widget", "limit_s", "image", "labels"};
  int trials = 0;
  for (const auto& s : w.screens) {
    if (s["kind"] != "trial") continue;
    ++trials;
    for (const auto& [key, value] : s.items()) EXPECT_TRUE(trialKeys.count(key)) << "the trial screen carries '" << key << "'";
    EXPECT_TRUE(s["labels"].empty()) << "layer-number trials offer no labels to click";
  }
  EXPECT_GT(trials, 0);
  server.stop(SIGTERM);
  // The truths are in the database, and none of them was in what the page got.
  const auto rows = exported("trials");
  std::string pages;
  for (const auto& s : w.screens) pages += s.dump();
  EXPECT_EQ(pages.find("truth"), std::string::npos);
  EXPECT_FALSE(rows[1][column(rows, "truth")].empty());
}

TEST_F(Serve, ATokenReachesOnlyItsOwnParticipant) {
  ServedStudy server(studyData("serve_tiny.toml"), db_, dir_);
  PageClient page(server.port());
  const std::string a = arrive(page, "pa"), b = arrive(page, "pb");
  ASSERT_NE(a, b);
  EXPECT_EQ(arrive(page, "pa"), a) << "the same link finds the same session (a reload of the arrival)";
  const json bScreen = walk(page, b, page.api(b, "display", display()).body, 0).screens.back();
  ASSERT_EQ(bScreen["kind"], "trial");
  const std::string sha = bScreen["image"]["sha256"];
  EXPECT_EQ(page.raw("/api/" + b + "/image/" + sha + ".png")->status, 200);
  EXPECT_EQ(page.raw("/api/" + a + "/image/" + sha + ".png")->status, 404) << "a's page was never shown b's stimulus";
  std::string wrong = a;
  wrong[0] = wrong[0] == '0' ? '1' : '0';
  EXPECT_EQ(page.screen(wrong).status, 404);
  EXPECT_EQ(page.raw("/p/" + wrong)->status, 404);
  // A reply with b's screen number on a's token does not answer b's trial.
  EXPECT_NE(page.api(a, "reply", {{"seq", bScreen["seq"]}, {"type", "answer"}, {"answer", 1}, {"rt_ms", 5}}).status, 200);
  EXPECT_EQ(page.screen(b).body["seq"], bScreen["seq"]);
}

TEST_F(Serve, HostileRequestsAreRefusedAndNothingIsStoredOfThem) {
  ServedStudy server(studyData("serve_tiny.toml"), db_, dir_);
  PageClient page(server.port());
  const std::string token = arrive(page, "p1");
  const json trial = walk(page, token, page.api(token, "display", display()).body, 0).screens.back();
  ASSERT_EQ(trial["kind"], "trial");
  const json seq = trial["seq"];
  for (const json& bad : {json{{"seq", seq}, {"type", "answer"}, {"answer", "two"}, {"rt_ms", 5}},
                          json{{"seq", seq}, {"type", "answer"}, {"answer", 0}, {"rt_ms", 5}},
                          json{{"seq", seq}, {"type", "answer"}, {"answer", 2}, {"rt_ms", -1}},
                          json{{"seq", seq}, {"type", "answer"}, {"answer", 2}},
                          json{{"seq", seq}, {"type", "answer"}, {"answer", {{"x", 1}}}, {"rt_ms", 5}},
                          json{{"seq", seq}, {"type", "delete"}}}) {
    const Reply r = page.api(token, "reply", bad);
    EXPECT_EQ(r.status, 400) << bad.dump();
    EXPECT_FALSE(r.body["error"].get<std::string>().empty());
  }
  EXPECT_EQ(page.post("/api/" + token + "/reply", "{not json").status, 400);
  EXPECT_EQ(page.post("/api/" + token + "/reply", "[1,2]").status, 400);
  EXPECT_EQ(page.post("/api/" + token + "/reply", std::string(100 * 1024, ' ')).status, 413) << "bodies are bounded";
  EXPECT_EQ(page.api(token, "display", {{"evil", json::array({1, 2})}}).status, 400);
  for (const char* path : {"/api/%s/image/../../../../etc/passwd", "/api/%s/image/..%%2f..%%2fetc%%2fpasswd.png", "/static/../study.db",
                           "/api/%s/image/0000000000000000000000000000000000000000000000000000000000000000.png", "/study.db"}) {
    char url[256];
    std::snprintf(url, sizeof url, path, token.c_str());
    const auto r = page.raw(url);
    EXPECT_EQ(r->status, 404) << url;
    EXPECT_EQ(r->body.find("SQLite"), std::string::npos);
  }
  EXPECT_EQ(page.arrive(kStudy, "PROLIFIC_PID=%3Cscript%3E").first, 400);
  EXPECT_EQ(page.arrive(kStudy, "pid=nobody").first, 400) << "the link names its participant with PROLIFIC_PID";
  EXPECT_EQ(page.arrive("other-study", "PROLIFIC_PID=p2").first, 404);
  // The trial is still open; the right answer goes through once, a second copy is stale.
  EXPECT_EQ(page.api(token, "reply", {{"seq", seq}, {"type", "onset"}, {"painted_ms", 1}}).status, 200);
  EXPECT_EQ(page.api(token, "reply", {{"seq", seq}, {"type", "answer"}, {"answer", 2}, {"rt_ms", 700}}).status, 200);
  EXPECT_EQ(page.api(token, "reply", {{"seq", seq}, {"type", "answer"}, {"answer", 3}, {"rt_ms", 700}}).status, 409);
  server.stop(SIGTERM);
  const auto trials = exported("trials");
  int responded = 0;
  for (std::size_t i = 1; i < trials.size(); ++i) responded += trials[i][column(trials, "responded")] == "1";
  EXPECT_EQ(responded, 1);
  EXPECT_EQ(trials[1][column(trials, "raw_answer")], "2");
  int refused = 0;
  const auto events = exported("events");
  for (const auto& e : events) refused += e[column(events, "kind")] == "refused-reply";
  EXPECT_EQ(refused, 6) << "each refused answer is logged as an event, none as an answer";
}

TEST_F(Serve, TheAdminPageNeedsItsTokenAndDropsFreeTheSlot) {
  ServedStudy server(studyData("serve_tiny.toml"), db_, dir_);
  PageClient page(server.port());
  EXPECT_EQ(page.raw("/admin")->status, 403);
  EXPECT_EQ(page.raw("/admin?token=" + std::string(64, 'a'))->status, 403);
  EXPECT_EQ(page.raw("/admin/status.json?token=x")->status, 403);
  const std::string admin = server.adminToken();
  const std::string waiting = arrive(page, "at-consent");  // arrived, not enrolled: listed apart from the slots
  page.api(waiting, "display", display());
  const std::string token = arrive(page, "p1");
  walk(page, token, page.api(token, "display", display()).body, 3);  // the 2 training trials and 1 test trial
  const std::string decliner = arrive(page, "declines");  // declined: ended, never "running"
  const json welcome = page.api(decliner, "display", display()).body;
  const json consent = page.api(decliner, "reply", {{"seq", welcome["seq"]}, {"type", "continue"}}).body;
  json after = page.api(decliner, "reply", {{"seq", consent["seq"]}, {"type", "consent"}, {"accepted", false}}).body;
  for (int i = 0; i < 5 && after["kind"] == "message"; ++i) after = page.api(decliner, "reply", {{"seq", after["seq"]}, {"type", "continue"}}).body;
  EXPECT_EQ(after["kind"], "end") << after.dump();
  const json status = page.get("/admin/status.json?token=" + admin).body;
  ASSERT_EQ(status["slots"].size(), 1u);
  const json& p1 = status["slots"][0];
  EXPECT_EQ(p1["participant"], "p1");
  EXPECT_EQ(p1["answered"], 1);
  EXPECT_EQ(p1["missing"], 0);
  EXPECT_EQ(p1["trials"], "3/10");
  EXPECT_EQ(p1["session"], "running");
  EXPECT_EQ(p1["screen"], "trial 2 of 8") << p1.dump();
  EXPECT_TRUE(p1["elapsed_s"].is_number() && p1["idle_s"].is_number() && p1["idle_s"] <= p1["elapsed_s"]) << p1.dump();
  ASSERT_EQ(status["arrived"].size(), 2u);
  std::map<std::string, std::string> arrivedState;
  for (const auto& a : status["arrived"]) arrivedState[a["participant"]] = a["session"];
  EXPECT_EQ(arrivedState, (std::map<std::string, std::string>{{"at-consent", "running"}, {"declines", "declined"}}));
  EXPECT_EQ(status["running"], 2);
  EXPECT_EQ(status["target"], 4);
  EXPECT_EQ(status["summary"], "1 slot assigned, 0 of 4 participants finished (the target); 2 running now, 0 idle; 1 answer and 0 missing "
                               "responses to test trials stored; 3 participants arrived at this server");
  const auto html = page.raw("/admin?token=" + admin);
  EXPECT_EQ(html->status, 200);
  EXPECT_NE(html->body.find("p1"), std::string::npos);
  EXPECT_NE(html->body.find("<meta http-equiv=\"refresh\" content=\"10\">"), std::string::npos) << "the page reloads itself";
  // Drop asks first: the page's drop button leads to a confirmation with the real (POST) drop.
  EXPECT_EQ(page.raw("/admin/drop?participant=p1&token=" + std::string(64, 'c'))->status, 403);
  const auto confirm = page.raw("/admin/drop?participant=p1&token=" + admin);
  EXPECT_EQ(confirm->status, 200);
  EXPECT_NE(confirm->body.find("<h1>Drop p1?</h1>"), std::string::npos) << confirm->body;
  EXPECT_NE(confirm->body.find("<form method=\"post\" action=\"/admin/drop\">"), std::string::npos) << confirm->body;
  EXPECT_EQ(page.screen(token).body["kind"], "trial") << "the confirmation page drops nobody";
  EXPECT_EQ(page.post("/admin/drop", "participant=p1&token=" + std::string(64, 'b'), "application/x-www-form-urlencoded").status, 403);
  EXPECT_EQ(page.post("/admin/drop", "participant=p1&token=" + admin, "application/x-www-form-urlencoded").status, 303);
  EXPECT_EQ(page.screen(token).body["kind"], "end");
  // The freed slot 0 goes to the next participant; p1 is refused.
  EXPECT_EQ(page.arrive(kStudy, "PROLIFIC_PID=p1").first, 409);
  const std::string next = arrive(page, "p2");
  walk(page, next, page.api(next, "display", display()).body, 0);
  const json later = page.get("/admin/status.json?token=" + admin).body;
  bool backFilled = false;
  for (const auto& s : later["slots"]) backFilled = backFilled || (s["participant"] == "p2" && s["slot"] == 0);
  EXPECT_TRUE(backFilled) << later.dump();
}

TEST_F(Serve, ASilentParticipantTimesOutAndTheSlotIsBackFilled) {
  ServedStudy server(studyData("serve_tiny.toml"), db_, dir_);  // timeout_minutes = 0.05: 3 s
  PageClient page(server.port());
  const std::string token = arrive(page, "quiet");
  walk(page, token, page.api(token, "display", display()).body, 0);
  const std::string early = arrive(page, "early");  // stays at the welcome: never enrolled
  EXPECT_EQ(page.api(early, "display", display()).body["kind"], "message");
  json screen;
  for (int i = 0; i < 100; ++i) {  // no request for 3 s: the session ends; polling then shows how
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    if (i >= 20 && (screen = page.screen(token).body)["kind"] == "end") break;
  }
  ASSERT_EQ(screen["kind"], "end") << screen.dump();
  EXPECT_EQ(screen["text"], tlab::study::ParticipantTexts().text("end.timed_out_replaced"));  // "... no request from this page for too long ..."
  EXPECT_EQ(page.arrive(kStudy, "PROLIFIC_PID=quiet").first, 409);
  const json earlyEnd = page.screen(early).body;  // nothing was stored of them: they may start again
  EXPECT_EQ(earlyEnd["kind"], "end");
  EXPECT_NE(earlyEnd["text"].get<std::string>().find("start again"), std::string::npos) << earlyEnd.dump();
  EXPECT_EQ(page.api(early, "display", display()).body["kind"], "message") << "a reload starts at the welcome again";
  const std::string next = arrive(page, "next");
  walk(page, next, page.api(next, "display", display()).body, 1);
  server.stop(SIGTERM);
  const auto participants = exported("participants");
  std::map<std::string, std::pair<std::string, std::string>> byId;
  for (std::size_t i = 1; i < participants.size(); ++i)
    byId[participants[i][column(participants, "participant")]] = {participants[i][column(participants, "slot")],
                                                                   participants[i][column(participants, "status")]};
  EXPECT_EQ(byId["quiet"].second, "dropped");
  EXPECT_EQ(byId["next"], std::make_pair(std::string("0"), std::string("active"))) << "the slot of the dropped participant";
}

TEST_F(Serve, AReloadShowsTheSameTrialAndARestartAfterAKillResumesIt) {
  int port = 0;
  std::string token;
  {
    ServedStudy server(studyData("serve_tiny.toml"), db_, dir_);
    port = server.port();
    PageClient page(port);
    token = arrive(page, "p1");
    const json trial = walk(page, token, page.api(token, "display", display()).body, 3).screens.back();
    ASSERT_EQ(trial["kind"], "trial");
    EXPECT_EQ(page.api(token, "reply", {{"seq", trial["seq"]}, {"type", "onset"}, {"painted_ms", 1}}).status, 200);
    const json reloaded = page.screen(token).body;  // the page reloads: the same screen, shown again
    EXPECT_EQ(reloaded, trial);
    const Reply second = page.api(token, "reply", {{"seq", trial["seq"]}, {"type", "onset"}, {"painted_ms", 2}});
    EXPECT_EQ(second.body["ok"], true) << "the onset is acknowledged once stored";
    EXPECT_EQ(server.stop(SIGKILL), -SIGKILL);
  }
  ServedStudy again(studyData("serve_tiny.toml"), db_, dir_, port);
  PageClient page(again.port());
  EXPECT_EQ(page.screen(token).status, 404) << "tokens do not outlive the server";
  const std::string resumed = arrive(page, "p1");
  const Walk w = walk(page, resumed, page.api(resumed, "display", display()).body);
  EXPECT_EQ(w.screens.back()["kind"], "end");
  EXPECT_EQ(w.answered, 7) << "the 3 answers acknowledged before the kill are not asked again";
  bool welcomeBack = false;
  for (const auto& s : w.screens) welcomeBack = welcomeBack || (s["kind"] == "message" && s["text"].get<std::string>().find("Welcome back") != std::string::npos);
  EXPECT_TRUE(welcomeBack);
  again.stop(SIGTERM);
  const auto sessions = exported("sessions");
  ASSERT_EQ(sessions.size(), 3u);
  EXPECT_EQ(sessions[1][column(sessions, "status")], "interrupted, resumed by session " + sessions[2][column(sessions, "session")]);
  EXPECT_EQ(sessions[1][column(sessions, "resumed_by")], sessions[2][column(sessions, "session")]);
  const auto trials = exported("trials");
  EXPECT_EQ(trials[4][column(trials, "showings")], "3") << "shown, reloaded, and shown again after the restart";
  for (std::size_t i = 1; i < trials.size(); ++i) EXPECT_EQ(trials[i][column(trials, "responded")], "1");
}

TEST_F(Serve, BadStartsAreOneLineAndWalkingIsRefusedOnline) {
  ServedStudy server(studyData("serve_tiny.toml"), db_, dir_);
  const auto taken = runCommand(commandLine({TLAB_EXE, "serve", studyData("serve_tiny.toml"), "--db", (dir_ / "other.db").string(), "--listen",
                                             "127.0.0.1:" + std::to_string(server.port()), "--quiet"}));
  EXPECT_EQ(taken.exitCode, 1);
  EXPECT_NE(taken.err.find("cannot listen on 127.0.0.1:" + std::to_string(server.port())), std::string::npos) << taken.err;
  EXPECT_EQ(std::count(taken.err.begin(), taken.err.end(), '\n'), 1) << taken.err;
  // Walking needs live views: with [online] live = false (turntables only) it is refused.
  const std::string turntables = (dir_ / "turntables.toml").string();
  std::ofstream(turntables) << readText(studyData("live_online.toml")) << "live = false\n";  // its [online] table is the last
  const auto walking = runCommand(commandLine({TLAB_EXE, "serve", turntables, "--db", (dir_ / "e.db").string(), "--quiet"}));
  EXPECT_EQ(walking.exitCode, 1);
  EXPECT_NE(walking.err.find("turntables.toml:26: tasks["), std::string::npos) << walking.err;
  EXPECT_NE(walking.err.find("live = false"), std::string::npos) << walking.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "e.db")) << "nothing is written before the checks pass";
  const auto unreachable = runCommand(commandLine({TLAB_EXE, "serve", studyData("serve_tiny.toml"), "--db",
                                                   "postgresql://tlab:secret@127.0.0.1:1/nothing", "--listen", "127.0.0.1:0", "--quiet"}));
  EXPECT_EQ(unreachable.exitCode, 1);
  EXPECT_NE(unreachable.err.find("cannot connect to PostgreSQL"), std::string::npos) << unreachable.err;
  EXPECT_EQ(unreachable.err.find("secret"), std::string::npos) << "the password is never printed";
  EXPECT_EQ(std::count(unreachable.err.begin(), unreachable.err.end(), '\n'), 1) << unreachable.err;
  const auto help = runCommand(commandLine({TLAB_EXE, "serve", "--help"}));
  EXPECT_NE(help.out.find("127.0.0.1:8080"), std::string::npos) << "the server binds to this machine unless told otherwise";
}

}  // namespace
}  // namespace tlab::testing
