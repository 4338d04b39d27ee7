// PassTimer::stopAfter (tlab bench render --until): the passes after the named one are skipped,
// further runs of the named one are not, and the timer says which ran. No GL: timing is off.
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

}  // namespace
}  // namespace tlab::render
