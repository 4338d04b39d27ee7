// Live views online (issue #30): the page's input check, the GL worker's frame queue (one frame
// per session, superseded requests dropped with their input handed on, sessions in turn, a rate
// per session) and the bounds of a live camera. No GL: the rendering is exercised end to end by
// the serve and browser tests.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "renderer/scene/scene_source.hpp"
#include "study/design/scene_catalog.hpp"
#include "study/run/camera_navigator.hpp"
#include "study/serve/live_frames.hpp"
#include "study/serve/view_input.hpp"

namespace tlab::study {
namespace {

using nlohmann::json;
using namespace std::chrono_literals;

std::string refusal(const json& input) {
  try {
    parseViewInput(input);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ViewInput, ReadsEveryFieldAndDescribesItForTheFrameLog) {
  const ViewInput v = parseViewInput(json::parse(R"({"dx": 12.5, "dy": -3, "forward": 2, "turn": -1, "point": [0.25, 1]})"));
  EXPECT_EQ(v.dx, 12.5);
  EXPECT_EQ(v.dy, -3.0);
  EXPECT_EQ(v.forward, 2);
  EXPECT_EQ(v.turn, -1);
  ASSERT_TRUE(v.point);
  EXPECT_EQ(*v.point, glm::vec2(0.25f, 1.0f));
  EXPECT_EQ(v.describe(), "drag 12.5,-3 key 2,-1 point 0.25,1");
  EXPECT_EQ(parseViewInput(json::object()).describe(), "start");
  EXPECT_TRUE(parseViewInput(json::object()).empty());
}

TEST(ViewInput, RefusesWhatNoPersonSends) {
  EXPECT_EQ(refusal(json::array()), "'input' must be an object");
  EXPECT_EQ(refusal({{"dx", "5"}}), "'dx' must be a number");
  EXPECT_EQ(refusal({{"dx", 4000.5}}), "'dx' is out of range");
  EXPECT_EQ(refusal({{"dy", -1e300}}), "'dy' is out of range");
  EXPECT_EQ(refusal({{"forward", 1.5}}), "'forward' must be a whole number of steps");
  EXPECT_EQ(refusal({{"turn", 41}}), "'turn' is out of range");
  EXPECT_EQ(refusal({{"point", {0.5}}}), "'point' must be [x, y]");
  EXPECT_EQ(refusal({{"point", {1.5, 0.5}}}), "'point' is out of range");
  EXPECT_EQ(refusal({{"point", {-0.1, 0.5}}}), "'point' must lie on the picture (0 to 1)");
  EXPECT_EQ(refusal({{"camera", "eye=0,0,0"}}), "unknown input 'camera' (expected dx, dy, forward, turn, point)");
  // NaN and infinity do not come through JSON text, but a parsed document may hold them.
  EXPECT_EQ(refusal({{"dx", std::numeric_limits<double>::quiet_NaN()}}), "'dx' is out of range");
  EXPECT_EQ(refusal({{"dx", std::numeric_limits<double>::infinity()}}), "'dx' is out of range");
}

TEST(ViewInput, LaterInputFollowsEarlierInput) {
  ViewInput a, b;
  a.dx = 3, a.forward = 1, a.point = glm::vec2(0.1f, 0.2f);
  b.dx = -1, b.dy = 2, b.turn = 1;
  const ViewInput sum = a.then(b);
  EXPECT_EQ(sum.dx, 2.0);
  EXPECT_EQ(sum.dy, 2.0);
  EXPECT_EQ(sum.forward, 1);
  EXPECT_EQ(sum.turn, 1);
  EXPECT_EQ(*sum.point, glm::vec2(0.1f, 0.2f));  // the latest cursor position: b has none, a's stays
  b.point = glm::vec2(0.9f, 0.9f);
  EXPECT_EQ(*a.then(b).point, glm::vec2(0.9f, 0.9f));
}

LiveRequest request(const std::string& session, std::shared_ptr<const LiveTrial> trial, double dx) {
  ViewInput in;
  in.dx = dx;
  return {session, std::move(trial), in};
}

bool ready(const std::future<LiveAnswer>& f) { return f.wait_for(0s) == std::future_status::ready; }

TEST(LiveFrameQueue, ANewerRequestOfTheSameSessionDropsTheWaitingOneAndTakesItsInput) {
  LiveFrameQueue queue(30.0);
  const auto trial = std::make_shared<const LiveTrial>();
  auto first = queue.submit(request("a", trial, 5));
  auto second = queue.submit(request("a", trial, 7));
  ASSERT_TRUE(ready(first));
  EXPECT_EQ(first.get().status, LiveAnswer::Status::Superseded);
  EXPECT_FALSE(ready(second));
  auto taken = queue.take(LiveClock::now());
  ASSERT_TRUE(taken);
  EXPECT_EQ(taken->request.input.dx, 12.0);  // nothing the participant did is lost
  EXPECT_FALSE(queue.take(LiveClock::now() + 1h));  // one frame, not two
  LiveAnswer frame;
  frame.status = LiveAnswer::Status::Frame;
  taken->answer.set_value(std::move(frame));
  EXPECT_EQ(second.get().status, LiveAnswer::Status::Frame);
}

TEST(LiveFrameQueue, InputOfAnotherTrialIsNotHandedOn) {
  LiveFrameQueue queue(30.0);
  auto old = queue.submit(request("a", std::make_shared<const LiveTrial>(), 5));
  const auto next = std::make_shared<const LiveTrial>();
  auto now = queue.submit(request("a", next, 7));
  auto taken = queue.take(LiveClock::now());
  ASSERT_TRUE(taken);
  EXPECT_EQ(taken->request.trial, next);
  EXPECT_EQ(taken->request.input.dx, 7.0);
}

TEST(LiveFrameQueue, SessionsAreServedInTurn) {
  LiveFrameQueue queue(1000.0);
  const auto trial = std::make_shared<const LiveTrial>();
  const LiveClock::time_point t0 = LiveClock::now();
  std::vector<std::future<LiveAnswer>> answers;
  for (const char* s : {"a", "b", "c"}) answers.push_back(queue.submit(request(s, trial, 1)));
  std::string served;
  auto t = t0;
  for (int round = 0; round < 6; ++round) {
    t += 1s;
    auto taken = queue.take(t);
    ASSERT_TRUE(taken);
    served += taken->request.session;
    if (taken->request.session == "a") answers.push_back(queue.submit(request("a", trial, 1)));  // a asks again at once
    else if (round < 3) answers.push_back(queue.submit(request(taken->request.session, trial, 1)));
  }
  // a, asking again after every frame, waits behind b and c each time: it never starves them.
  EXPECT_EQ(served, "abcabc");
}

TEST(LiveFrameQueue, ASessionGetsNoMoreThanItsFramesPerSecond) {
  LiveFrameQueue queue(10.0);  // 100 ms apart
  const auto trial = std::make_shared<const LiveTrial>();
  const LiveClock::time_point t0 = LiveClock::now();
  auto first = queue.submit(request("a", trial, 1));
  auto taken = queue.take(t0);
  ASSERT_TRUE(taken);
  auto second = queue.submit(request("a", trial, 1));
  EXPECT_FALSE(queue.take(t0 + 99ms));
  ASSERT_TRUE(queue.nextDue());
  EXPECT_EQ(*queue.nextDue(), t0 + std::chrono::duration_cast<LiveClock::duration>(std::chrono::duration<double>(0.1)));
  auto b = queue.submit(request("b", trial, 1));  // another session is not held up by a's rate
  auto other = queue.take(t0 + 99ms);
  ASSERT_TRUE(other);
  EXPECT_EQ(other->request.session, "b");
  EXPECT_TRUE(queue.take(t0 + 100ms));
  EXPECT_FALSE(queue.nextDue());
}

TEST(LiveFrameQueue, ClearAnswersEveryWaitingRequest) {
  LiveFrameQueue queue(30.0);
  auto a = queue.submit(request("a", std::make_shared<const LiveTrial>(), 1));
  queue.clear();
  ASSERT_TRUE(ready(a));
  EXPECT_EQ(a.get().status, LiveAnswer::Status::Superseded);
  EXPECT_FALSE(queue.nextDue());
}

TEST(LiveBounds, WalkingWithoutCollisionStopsAtTheBoundsOfTheScene) {
  auto scene = std::make_shared<const render::Scene>(render::loadScene("builtin:walkthrough?seed=1", sceneCatalog()));
  ASSERT_TRUE(scene->camera);
  const LiveTrial trial{scene, {}, Navigation::Walk, *scene->camera};
  const render::BoundingSphere sphere = scene->boundingSphere();
  const float reach = 1.5f * std::max(sphere.radius, glm::length(trial.start.eye - sphere.center));
  EXPECT_TRUE(withinLiveBounds(trial, trial.start));
  CameraNavigator walker(Navigation::Walk, trial.start, sphere.radius / 10.0f);
  ViewInput step;
  step.forward = 1;
  for (int i = 0; i < 1000; ++i) steer(walker, trial, step);  // a motion that leaves the bounds is not made
  const float distance = glm::length(walker.camera().eye - sphere.center);
  EXPECT_LE(distance, reach);
  EXPECT_GT(distance, reach - sphere.radius / 10.0f);  // it walked as far as it may
  render::Camera far = trial.start;
  far.eye = sphere.center + glm::vec3(reach * 1.01f, 0.0f, 0.0f);
  EXPECT_FALSE(withinLiveBounds(trial, far));
  far.eye = glm::vec3(std::nanf(""), 0.0f, 0.0f);
  EXPECT_FALSE(withinLiveBounds(trial, far));
}

TEST(LiveBounds, TheLensFollowsTheCursorOnlyInTheDynamicStylesActiveMode) {
  StimulusKey key;
  key.style = "dynamic";
  EXPECT_FALSE(lensFollowsCursor(key));
  key.renderSettings = {"mode=active"};
  EXPECT_TRUE(lensFollowsCursor(key));
  key.style = "constant";
  EXPECT_FALSE(lensFollowsCursor(key));
}

}  // namespace
}  // namespace tlab::study
