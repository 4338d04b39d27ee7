// Task settings as declared ("Tasks as modules": each task lists its keys, defaults and, for
// numbers, the range it can use): a value outside the range, or a fraction where a whole number
// is counted, is refused where it is given, naming the task and the key. (Before, attempts=1e12
// reached an int conversion, min-layer=2.5 and time-limit=-1 were taken as given.)
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tasks/task_registry.hpp"
#include "tasks/task_settings.hpp"

using namespace tlab::tasks;

namespace {

std::string refusal(const std::string& task, const std::string& setting) {
  try {
    makeTask(task)->settings({setting});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST(TaskSettings, ValuesOutsideTheDeclaredRangeOrNotWholeAreRefused) {
  EXPECT_EQ(refusal("layer-index", "attempts=1e12"),
            "task 'layer-index': setting 'attempts' = 1e12: expected a whole number in [1, 1000000]");
  EXPECT_EQ(refusal("layer-index", "min-layer=2.5"),
            "task 'layer-index': setting 'min-layer' = 2.5: expected a whole number in [1, 1000]");
  EXPECT_EQ(refusal("layer-index", "time-limit=-1"),
            "task 'layer-index': setting 'time-limit' = -1: expected a number in [0.5, 86400]");
  EXPECT_EQ(refusal("nearest-point", "candidates=7"),
            "task 'nearest-point': setting 'candidates' = 7: expected a whole number in [2, 6]");
  EXPECT_EQ(refusal("nearest-point", "euclidean-trap-share=1.5"),
            "task 'nearest-point': setting 'euclidean-trap-share' = 1.5: expected a number in [0, 1]");
  EXPECT_EQ(refusal("gauge-figure", "max-slant=91"), "task 'gauge-figure': setting 'max-slant' = 91: expected a number in [0, 90]");
  EXPECT_EQ(refusal("relative-depth", "layer-b=0"), "task 'relative-depth': setting 'layer-b' = 0: expected a whole number in [1, 1000]");
  EXPECT_EQ(refusal("follow-boundary", "marks=1"), "task 'follow-boundary': setting 'marks' = 1: expected a whole number in [2, 100]");
  EXPECT_EQ(refusal("layer-index", "attempts=many"), "task 'layer-index': setting 'attempts' expects a number, got 'many'");
  // The ends of a range are allowed, and a whole number may be written as one (3.0).
  for (const char* ok : {"attempts=1", "attempts=1000000", "min-layer=3.0", "time-limit=0.5", "time-limit=86400"})
    EXPECT_EQ(refusal("layer-index", ok), "(accepted)") << ok;
  EXPECT_EQ(makeTask("layer-index")->settings({"min-layer=3.0"}).number("min-layer"), 3.0);
  // Text settings take any text.
  EXPECT_EQ(refusal("counting", "kind=cone"), "(accepted)");
}

// Every task's defaults lie within their own ranges, whole where they must be, and the listing
// says what each number takes.
TEST(TaskSettings, EveryDefaultMeetsItsDeclaration) {
  for (const auto& name : taskNames()) {
    const auto task = makeTask(name);
    const TaskSettings defaults = task->settings({});
    for (const auto& spec : task->settingSpecs()) {
      if (!spec.numeric) {
        EXPECT_EQ(spec.rangeText(), "") << name << " " << spec.key;
        continue;
      }
      const double v = defaults.number(spec.key);
      EXPECT_TRUE(v >= spec.minValue && v <= spec.maxValue) << name << " " << spec.key;
      EXPECT_TRUE(!spec.whole || v == std::floor(v)) << name << " " << spec.key;
      EXPECT_LT(spec.maxValue, 1e31) << name << " " << spec.key << ": a declared range, not the unbounded one";
      EXPECT_NE(spec.rangeText().find(" in ["), std::string::npos);
    }
  }
}
