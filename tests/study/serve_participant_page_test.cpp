// tlab serve as a participant's page meets it. An answer that comes too late is stored as late,
// never dropped silently: one sent after the trial's time limit (the page's clock) is kept with
// its text, scored as missing and noted "late"; one sent to a trial the server has already closed
// is kept as a "late-answer" event. A session belongs to the browser that started it (its
// tlab-browser cookie): another is refused until the session has been silent for the time-out,
// and the takeover is logged.
#include <gtest/gtest.h>

#include <thread>

#include "tests/study/serve_test_client.hpp"
#include "tests/study/served_study.hpp"

namespace tlab::testing {
namespace {

using nlohmann::json;

TEST(ServeLateAnswer, AnAnswerAfterTheLimitIsStoredAsLateAndOneToAClosedTrialAsAnEvent) {
  const auto dir = freshDir("ServeLateAnswer");
  const std::string db = (dir / "study.db").string();
  ServedStudy server(studyData("serve_tiny.toml"), db, dir);  // time_limit = 30 s
  PageClient page(server.port());
  const auto [status, token] = page.arrive("serve-tiny", "PROLIFIC_PID=late");
  ASSERT_EQ(status, 303);
  const json trial = walk(page, token, page.api(token, "display", display()).body, 0).screens.back();
  ASSERT_EQ(trial["kind"], "trial") << trial.dump();
  EXPECT_EQ(page.api(token, "reply", {{"seq", trial["seq"]}, {"type", "onset"}, {"painted_ms", 5}}).status, 200);
  const Reply late = page.api(token, "reply", {{"seq", trial["seq"]}, {"type", "answer"}, {"answer", 2}, {"rt_ms", 31500.0}});
  ASSERT_EQ(late.status, 200) << late.body.dump();
  // The same answer sent again (a page that did not see the acknowledgement): the trial has gone.
  const Reply again = page.api(token, "reply", {{"seq", trial["seq"]}, {"type", "answer"}, {"answer", 1}, {"rt_ms", 900.0}});
  EXPECT_EQ(again.status, 409) << again.body.dump();
  const Walk w = walk(page, token, again.body["screen"], 1);  // the next trial stores the events seen since
  EXPECT_EQ(w.answered, 1);
  server.stop(SIGTERM);

  const auto trials = exportedTable(db, dir, "trials");
  ASSERT_GE(trials.size(), 3u);
  EXPECT_EQ(trials[1][column(trials, "raw_answer")], "2") << "the late answer's text is kept";
  EXPECT_EQ(trials[1][column(trials, "answered")], "0") << "over the limit: scored as missing";
  EXPECT_EQ(trials[1][column(trials, "note")], "late: answered 1.500 s after the time limit");
  const auto events = exportedTable(db, dir, "events");
  int lateEvents = 0;
  for (std::size_t i = 1; i < events.size(); ++i)
    if (events[i][column(events, "kind")] == "late-answer") {
      ++lateEvents;
      const json detail = json::parse(events[i][column(events, "detail")]);
      EXPECT_EQ(detail["screen"], trial["seq"]);
      EXPECT_EQ(json::parse(detail["body"].get<std::string>())["answer"], 1);
    }
  EXPECT_EQ(lateEvents, 1);
  std::filesystem::remove_all(dir);
}

TEST(ServeBrowserBinding, AnotherBrowserIsRefusedUntilTheSessionWasSilentForTheTimeOutAndTheTakeoverIsLogged) {
  const auto dir = freshDir("ServeBrowserBinding");
  const std::string db = (dir / "study.db").string();
  ServedStudy server(studyData("serve_tiny.toml"), db, dir);  // timeout_minutes = 0.05: 3 s
  PageClient first(server.port(), "other=1; tlab-browser=0123456789abcdef0123456789abcdef");
  PageClient second(server.port(), "tlab-browser=fedcba9876543210fedcba9876543210");
  PageClient bare(server.port());
  const auto [status, token] = first.arrive("serve-tiny", "PROLIFIC_PID=bound");
  ASSERT_EQ(status, 303);
  EXPECT_EQ(first.api(token, "display", display()).body["kind"], "message");
  EXPECT_EQ(first.screen(token).status, 200);
  const Reply refused = second.screen(token);  // the same link, opened in another browser
  EXPECT_EQ(refused.status, 403) << refused.body.dump();
  EXPECT_NE(refused.body["error"].get<std::string>().find("another browser"), std::string::npos);
  EXPECT_EQ(bare.screen(token).status, 403) << "a request without the browser's cookie is another browser too";
  EXPECT_EQ(second.api(token, "reply", {{"seq", 1}, {"type", "continue"}}).status, 403);
  EXPECT_EQ(first.screen(token).status, 200) << "the first browser goes on";
  // The first browser goes quiet; the other one asks now and then (its refused requests do not
  // count as the session's activity) and is let in once 3 s of silence have passed.
  Reply taken{403, {}};
  for (int i = 0; i < 150 && taken.status == 403; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    taken = second.screen(token);
  }
  ASSERT_EQ(taken.status, 200) << "the other browser is let in after the time-out of silence";
  EXPECT_EQ(first.screen(token).status, 403) << "the session now belongs to the browser that took it over";
  // Not enrolled yet, the silent session has ended at the welcome ("start again"): the new browser does.
  for (int i = 0; i < 100 && taken.body.value("kind", "") != "end"; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    taken = second.screen(token);
  }
  ASSERT_EQ(taken.body["kind"], "end") << taken.body.dump();
  const Walk w = walk(second, token, second.api(token, "display", display()).body, 1);
  EXPECT_EQ(w.answered, 1);
  server.stop(SIGTERM);
  EXPECT_NE(server.stderrText().find("participant 'bound': session taken over by another browser"), std::string::npos) << server.stderrText();
  const auto events = exportedTable(db, dir, "events");
  int takeovers = 0;
  for (std::size_t i = 1; i < events.size(); ++i)
    if (events[i][column(events, "kind")] == "takeover") {
      ++takeovers;
      EXPECT_EQ(json::parse(events[i][column(events, "detail")]), json({{"from", "01234567"}, {"to", "fedcba98"}}));
    }
  EXPECT_EQ(takeovers, 1);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tlab::testing
