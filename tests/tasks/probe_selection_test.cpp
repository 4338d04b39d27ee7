#include <gtest/gtest.h>

#include "renderer/scene/scene_source.hpp"
#include "tasks/question_json.hpp"
#include "tasks/task_registry.hpp"

namespace tlab::tasks {
namespace {

std::vector<Question> probeOpenCylinders(const std::string& taskName, int count, std::uint64_t seed,
                                         std::vector<std::string> settings = {}) {
  static const render::Scene scene = render::loadScene("builtin:open-cylinders?segments=48&rings=4");
  const auto task = makeTask(taskName);
  return task->probe({scene, *scene.camera, 400, 300, count, seed, task->settings(settings)});
}

std::string dump(const std::vector<Question>& qs, std::size_t n) {
  nlohmann::json j = nlohmann::json::array();
  for (std::size_t i = 0; i < n; ++i) j.push_back(toJson(qs[i]));
  return j.dump();
}

class ProbeSelection : public ::testing::TestWithParam<std::string> {};

TEST_P(ProbeSelection, SameSeedSameQuestionsAndQuestionKIndependentOfTheCount) {
  const auto four = probeOpenCylinders(GetParam(), 4, 17);
  const auto again = probeOpenCylinders(GetParam(), 4, 17);
  const auto two = probeOpenCylinders(GetParam(), 2, 17);
  const auto other = probeOpenCylinders(GetParam(), 4, 18);
  ASSERT_EQ(four.size(), 4u);
  EXPECT_EQ(dump(four, 4), dump(again, 4));
  EXPECT_EQ(dump(four, 2), dump(two, 2));
  EXPECT_NE(dump(four, 4), dump(other, 4));
}

TEST_P(ProbeSelection, EveryQuestionMeetsItsChecksAndIsInsideTheImage) {
  for (const auto& q : probeOpenCylinders(GetParam(), 6, 5)) {
    EXPECT_EQ(q.task, GetParam());
    ASSERT_FALSE(q.checks.empty());
    for (const auto& c : q.checks) {
      if (c.rule.find("differs") != std::string::npos || c.rule.find("same layer") != std::string::npos)
        EXPECT_EQ(c.value, c.required) << c.rule;
      else
        EXPECT_GE(c.value, c.required) << c.rule;
    }
    for (const auto& p : q.points) {
      EXPECT_GE(p.pixel.x, 8.0);
      EXPECT_GE(p.pixel.y, 8.0);
      EXPECT_LE(p.pixel.x, 400.0 - 8.0);
      EXPECT_LE(p.pixel.y, 300.0 - 8.0);
    }
    // Labels within a question are distinct.
    const auto labels = q.labels();
    EXPECT_EQ(std::set<std::string>(labels.begin(), labels.end()).size(), labels.size());
  }
}

INSTANTIATE_TEST_SUITE_P(Tasks, ProbeSelection, ::testing::Values("layer-index", "follow-boundary", "nearest-point"));

TEST(ProbeSelectionMargins, SettableMarginsAreRespected) {
  for (const auto& q : probeOpenCylinders("nearest-point", 4, 2, {"margin=0.4", "euclidean-trap-share=0"}))
    EXPECT_GE(q.checks.at(0).value, 0.4);
  for (const auto& q : probeOpenCylinders("follow-boundary", 4, 2, {"margin=0.5", "marks=3"})) {
    EXPECT_GE(q.checks.at(0).value, 0.5);
    EXPECT_EQ(q.points.size(), 5u);
  }
  for (const auto& q : probeOpenCylinders("layer-index", 4, 2, {"min-layer=3"})) EXPECT_GE(std::get<std::int64_t>(q.truth), 3);
}

TEST(ProbeSelectionMargins, PixelSeparationBetweenLayerProbes) {
  const auto qs = probeOpenCylinders("layer-index", 8, 4, {"min-separation-px=30"});
  for (std::size_t i = 0; i < qs.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) EXPECT_GE(glm::length(qs[i].points[0].pixel - qs[j].points[0].pixel), 30.0);
}

TEST(TaskRegistry, NamesAndErrors) {
  for (const auto& name : taskNames()) EXPECT_EQ(makeTask(name)->name(), name);
  try {
    makeTask("layers");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("layer-index, follow-boundary"), std::string::npos);
  }
  EXPECT_THROW(makeTask("nearest-point")->settings({"margin=lots"}), std::invalid_argument);
  EXPECT_THROW(makeTask("nearest-point")->settings({"colour=red"}), std::invalid_argument);
  EXPECT_EQ(makeTask("nearest-point")->settings({"time-limit=60"}).number("time-limit"), 60.0);
}

}  // namespace
}  // namespace tlab::tasks
