// The parts of `tlab replay` that need no GL: how long each logged frame stayed on screen, the
// ffmpeg concat list, why a frame is thought to differ (another GL, another tlab, frames rendered
// but not logged, or a changed log), the verdict line and the page.
#include <gtest/gtest.h>

#include "study/analyze/replay_listing.hpp"
#include "study/replay/replay_outputs.hpp"
#include "study/replay/trial_replay.hpp"

namespace tlab::study {
namespace {

LoggedFrame frameAt(int index, std::int64_t shownNs, std::int64_t session = 1, std::string input = "drag 1,0") {
  LiveFrame f;
  f.index = index;
  f.shownNs = shownNs;
  f.input = std::move(input);
  f.sha256 = std::string(64, '0' + char(index % 10));
  return {f, session};
}

// Three frames at 0, 40 and 100 ms, answered at 300 ms, by GL "llvmpipe" and tlab 1.0.
LoggedTrial threeFrames() {
  LoggedTrial t;
  t.participant = "P1";
  t.plan.sequence = 4;
  t.plan.taskId = "count";
  t.plan.stimulus.width = t.plan.stimulus.height = 160;
  t.frames = {frameAt(0, 1'000'000'000, 1, "start"), frameAt(1, 1'040'000'000), frameAt(2, 1'100'000'000, 1, "key 1,0; point 0.5,<0.25>")};
  t.responseNs = 1'300'000'000;
  t.correct = true;
  t.answer = "5";
  t.truth = "5";
  t.rtSeconds = 0.25;
  t.sessions[1] = {"window", "llvmpipe", "1.0"};
  return t;
}

TEST(ReplayParts, EachFrameStaysUntilTheNextAndTheLastUntilTheAnswer) {
  const LoggedTrial t = threeFrames();
  EXPECT_DOUBLE_EQ(shownSeconds(t, 0), 0.04);
  EXPECT_DOUBLE_EQ(shownSeconds(t, 1), 0.06);
  EXPECT_DOUBLE_EQ(shownSeconds(t, 2), 0.2);
}

TEST(ReplayParts, AShowingThatEndedWithoutTheAnswerKeepsItsLastFrameOneSecond) {
  LoggedTrial t = threeFrames();
  t.frames.insert(t.frames.begin() + 2, frameAt(0, 5'000'000'000, 2, "start"));  // shown again in session 2
  t.frames.back().frame.shownNs = 5'100'000'000;
  EXPECT_DOUBLE_EQ(shownSeconds(t, 1), 1.0);
  t.responseNs = 0;  // not answered
  EXPECT_DOUBLE_EQ(shownSeconds(t, 3), 1.0);
}

TEST(ReplayParts, ConcatListNamesEveryFrameWithItsDurationAndRepeatsTheLast) {
  const LoggedTrial t = threeFrames();
  EXPECT_EQ(concatList(t, "/tmp/it's"),
            "ffconcat version 1.0\n"
            "file '/tmp/it'\\''s/frame-000000.png'\nduration 0.040000\n"
            "file '/tmp/it'\\''s/frame-000001.png'\nduration 0.060000\n"
            "file '/tmp/it'\\''s/frame-000002.png'\nduration 0.200000\n"
            "file '/tmp/it'\\''s/frame-000002.png'\n");
}

TEST(ReplayParts, WhyAFrameDiffersNamesTheGlTheVersionOrAGap) {
  LoggedTrial t = threeFrames();
  EXPECT_EQ(whyDifferent(t, 1, {"llvmpipe", "1.0"}),
            "same GL ('llvmpipe') and tlab version (1.0) as the session: the logged hash or camera was changed, or the renderer is not "
            "deterministic here");
  EXPECT_EQ(whyDifferent(t, 1, {"NVIDIA H200", "1.1"}),
            "session 1 rendered with GL 'llvmpipe', this replay with 'NVIDIA H200'; session 1 ran tlab 1.0, this replay 1.1");
  t.frames[2].frame.index = 5;
  EXPECT_EQ(whyDifferent(t, 2, {"llvmpipe", "1.0"}),
            "frames 2 to 4 were rendered but not logged (the renderer's state across frames differs)");
  t.sessions.clear();
  EXPECT_EQ(whyDifferent(t, 1, {"llvmpipe", "1.0"}), "session 1 stored no GL renderer; session 1 stored no tlab version");
}

TEST(ReplayParts, VerdictCountsTheIdenticalFrames) {
  ReplayCheck c;
  c.frames = {{"a", true, ""}, {"b", false, "why"}, {"c", true, ""}};
  EXPECT_EQ(c.identical(), 2);
  EXPECT_EQ(c.summary(), "2 of 3 frames identical");
}

TEST(ReplayParts, PageShowsEveryFrameItsInputEscapedAndTheAnswer) {
  const LoggedTrial t = threeFrames();
  ReplayCheck c;
  c.frames = {{t.frames[0].frame.sha256, true, ""}, {"f00d", false, "session 1 ran tlab 1.0, this replay 1.1"}, {t.frames[2].frame.sha256, true, ""}};
  const std::string page = replayPage(t, c, "replay-frames");
  EXPECT_NE(page.find("<p class=\"verdict\" id=\"verdict\">2 of 3 frames identical</p>"), std::string::npos);
  EXPECT_NE(page.find("key 1,0; point 0.5,&lt;0.25&gt;"), std::string::npos) << "the input, escaped";
  EXPECT_EQ(page.find("point 0.5,<0.25>"), std::string::npos);
  EXPECT_NE(page.find("<tr class=\"differs\" data-frame=\"1\">"), std::string::npos);
  EXPECT_NE(page.find("this replay 1.1"), std::string::npos);
  EXPECT_NE(page.find("\"src\":\"replay-frames/frame-000002.png\""), std::string::npos);
  EXPECT_NE(page.find("“5”, correct (truth 5), 250.0 ms after the onset"), std::string::npos);
}

TEST(ReplayParts, TheCommandQuotesTheDatabaseAndAnyParticipantIdForAShell) {
  const ReplayableTrial t{"P'01; rm -rf /", 3, "test", "count", 12};
  EXPECT_EQ(replayCommand("my study.db", t),
            "tlab replay 'my study.db' --participant 'P'\\''01; rm -rf /' --trial 3 --html 'replay-P_01__rm_-rf__-trial3.html'");
}

}  // namespace
}  // namespace tlab::study
