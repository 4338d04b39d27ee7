#include <gtest/gtest.h>

#include "task_test_scenes.hpp"
#include "tasks/counting/counting_task.hpp"
#include "tasks/letter_patterns.hpp"
#include "tasks/pattern/pattern_task.hpp"
#include "tasks/scene_targets.hpp"
#include "tasks/scoring.hpp"
#include "tasks/target_discovery/target_discovery_task.hpp"

namespace tlab::tasks {
namespace {

using render::Role;
using testing::boxAt;

ProbeRequest requestFor(const render::Scene& scene, const Task& task, std::vector<std::string> settings = {}) {
  render::Camera camera;
  camera.eye = {0.0f, 12.0f, 12.0f};
  return {scene, camera, 320, 240, 1, 1, task.settings(settings)};
}

TEST(ObjectKind, NameWithoutItsNumber) {
  EXPECT_EQ(objectKind("cone-3"), "cone");
  EXPECT_EQ(objectKind("cone_12"), "cone");
  EXPECT_EQ(objectKind("red cone 7"), "red cone");
  EXPECT_EQ(objectKind("cone"), "cone");
  EXPECT_EQ(objectKind("R2D2"), "R2D");
}

TEST(Counting, CountsTargetsOrAKindAndScoresRelativeError) {
  render::Scene scene;
  scene.objects.push_back(boxAt("cone-1", {0, 0}, Role::Target));
  scene.objects.push_back(boxAt("cone-2", {1, 0}, Role::Target));
  scene.objects.push_back(boxAt("dog-1", {2, 0}, Role::Target));
  scene.objects.push_back(boxAt("cone-3", {3, 0}, Role::Distractor));
  scene.objects.push_back(boxAt("wall", {4, 0}, Role::Opaque));
  const CountingTask task;
  const auto targets = task.probe(requestFor(scene, task));
  ASSERT_EQ(targets.size(), 1u);
  EXPECT_EQ(std::get<std::int64_t>(targets[0].truth), 3);
  const Score s = task.score(targets[0], {"4", 20.0});
  EXPECT_FALSE(s.correct);
  EXPECT_DOUBLE_EQ(*s.error, 1.0 / 3.0);
  const auto cones = task.probe(requestFor(scene, task, {"kind=cone"}));
  EXPECT_EQ(std::get<std::int64_t>(cones[0].truth), 3);
  EXPECT_NE(cones[0].text.find("cone"), std::string::npos);
  EXPECT_EQ(std::get<std::int64_t>(task.probe(requestFor(scene, task, {"kind=dog"}))[0].truth), 1);
  EXPECT_THROW(task.probe(requestFor(scene, task, {"kind=cat"})), std::runtime_error);
  ProbeRequest two = requestFor(scene, task);
  two.count = 2;
  EXPECT_THROW(task.probe(two), std::invalid_argument);
}

TEST(TargetDiscovery, TruthIsTheFloorPointOfTheUniqueTargetScoredByErrorDistance) {
  render::Scene scene;
  scene.objects.push_back(boxAt("dog", {2.0, -1.0}, Role::Target));
  scene.objects.push_back(boxAt("cat", {-3.0, 4.0}, Role::Distractor));
  const TargetDiscoveryTask task;
  const auto q = task.probe(requestFor(scene, task, {"correct-within=0.6"}));
  ASSERT_EQ(q.size(), 1u);
  const glm::dvec2 truth = std::get<glm::dvec2>(q[0].truth);
  EXPECT_NEAR(truth.x, 2.0, 1e-6);
  EXPECT_NEAR(truth.y, -1.0, 1e-6);
  const Score near = task.score(q[0], {"2.3,-1.4", std::nullopt});
  EXPECT_NEAR(*near.error, 0.5, 1e-6);
  EXPECT_TRUE(near.correct);
  const Score far = task.score(q[0], {"-3,4", std::nullopt});
  EXPECT_NEAR(*far.error, std::sqrt(25.0 + 25.0), 1e-6);
  EXPECT_FALSE(far.correct);
  scene.objects.push_back(boxAt("dog-2", {0.0, 0.0}, Role::Target));
  EXPECT_THROW(task.probe(requestFor(scene, task)), std::runtime_error);  // no longer unique
}

TEST(Pattern, TargetsFormingALetterAmongDistractors) {
  for (const char letter : patternLetters()) {
    render::Scene scene;
    int i = 0;
    for (const auto& p : letterFloorPositions(letter, {-3.0, -4.0}, 1.2, 0.9))
      scene.objects.push_back(boxAt("cone-" + std::to_string(++i), p, Role::Target));
    scene.objects.push_back(boxAt("cone-red-sphere", {6.0, 6.0}, Role::Distractor));
    scene.objects.push_back(boxAt("box-1", {-6.0, 5.0}, Role::Distractor));
    const PatternTask task;
    const auto q = task.probe(requestFor(scene, task));
    ASSERT_EQ(q.size(), 1u);
    EXPECT_EQ(std::get<std::string>(q[0].truth), std::string(1, letter));
    EXPECT_TRUE(task.score(q[0], {std::string(1, char(std::tolower(letter))), std::nullopt}).correct);
    const char other = letter == 'C' ? 'X' : 'C';
    EXPECT_FALSE(task.score(q[0], {std::string(1, other), std::nullopt}).correct);
  }
}

TEST(Pattern, TargetsThatFormNoLetterAreRejected) {
  render::Scene scene;
  for (int i = 0; i < 13; ++i) scene.objects.push_back(boxAt("cone-" + std::to_string(i), {i * 0.7, (i * i) % 5}, Role::Target));
  const PatternTask task;
  EXPECT_THROW(task.probe(requestFor(scene, task)), std::runtime_error);
}

}  // namespace
}  // namespace tlab::tasks
