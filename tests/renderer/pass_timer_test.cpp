// PassTimer::stopAfter (tlab bench render --until): the passes after the named one are skipped,
// further runs of the named one are not, and the timer says which ran; PassTimer::part (tlab bench
// render --parts): a pass's parts run whether timed or not, and are listed only when asked for.
// No GL: timing is off.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "renderer/frame/pass_timer.hpp"

namespace tlab::render {
namespace {

std::vector<std::string> runFrame(PassTimer& timer, const std::vector<std::string>& names) {
  std::vector<std::string> ran;
  for (const auto& name : names) timer.time(name, [&] { ran.push_back(name); });
  return ran;
}

TEST(PassTimer, EveryPassRunsWithoutAStop) {
  PassTimer timer(false);
  EXPECT_EQ(runFrame(timer, {"fill", "sort", "connect", "compose"}),
            (std::vector<std::string>{"fill", "sort", "connect", "compose"}));
  EXPECT_TRUE(timer.ran("compose"));
}

TEST(PassTimer, PassesAfterTheStopAreSkipped) {
  PassTimer timer(false);
  timer.stopAfter("sort");
  EXPECT_EQ(runFrame(timer, {"fill", "sort", "connect", "solve", "compose"}), (std::vector<std::string>{"fill", "sort"}));
  EXPECT_TRUE(timer.ran("sort"));
  EXPECT_FALSE(timer.ran("connect"));
  ASSERT_EQ(timer.passes().size(), 2u);  // a skipped pass has no time either
  EXPECT_EQ(timer.passes()[1].first, "sort");
}

TEST(PassTimer, FurtherRunsOfTheLastPassStillRun) {
  // Depth peeling's frame: peel and blend per layer; stopping after "peel" peels every layer.
  PassTimer timer(false);
  timer.stopAfter("peel");
  EXPECT_EQ(runFrame(timer, {"peel", "blend", "peel", "blend", "peel"}), (std::vector<std::string>{"peel", "peel", "peel"}));
}

TEST(PassTimer, AStopThatNeverComesLeavesEveryPassRunning) {
  PassTimer timer(false);
  timer.stopAfter("connect");
  EXPECT_EQ(runFrame(timer, {"fill", "compose"}), (std::vector<std::string>{"fill", "compose"}));
  EXPECT_FALSE(timer.ran("connect"));  // the renderer turns this into "--until: ... has no pass"
}

TEST(PassTimer, PartsRunUntimedUnlessAskedFor) {
  PassTimer timer(false);
  int ran = 0;
  timer.time("connect", [&] {
    timer.part("connect phase 1", [&] { ++ran; });
    timer.part("connect phase 2", [&] { ++ran; });
  });
  EXPECT_EQ(ran, 2);
  EXPECT_TRUE(timer.parts().empty());
  timePart(nullptr, "solve step", [&] { ++ran; });  // a pass called without a timer (tests, tools)
  EXPECT_EQ(ran, 3);
}

TEST(PassTimer, PartsOfOneNameAddUpTheirTimesAndCountInTheOrderTheyFirstRan) {
  PassTimer timer(false);
  timer.timeParts(true);
  timer.time("solve", [&] {
    for (int step = 0; step < 20; ++step) timePart(&timer, "solve beta frontier step", [] {});
    timer.part("solve gamma frontier step", [] {});
  });
  timer.time("compose", [&] { timer.part("compose read-back", [] {}); });
  ASSERT_EQ(timer.parts().size(), 3u);
  EXPECT_EQ(timer.parts()[0].name, "solve beta frontier step");
  EXPECT_EQ(timer.parts()[0].count, 20);
  EXPECT_EQ(timer.parts()[1].name, "solve gamma frontier step");
  EXPECT_EQ(timer.parts()[1].count, 1);
  EXPECT_EQ(timer.parts()[2].name, "compose read-back");
  for (const auto& p : timer.parts()) EXPECT_GE(p.ms, 0.0) << p.name;
  EXPECT_EQ(timer.passes().size(), 2u);  // parts are not passes
}

}  // namespace
}  // namespace tlab::render
