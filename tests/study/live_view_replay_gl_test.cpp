// A live view's frames as a frame log records them (LiveView::rendered(): the exact camera and
// the dynamic lens where pointAt put it) render to the same pixels on a second LiveView through
// frameFrom(camera, lens), in the same order — what `tlab replay` relies on — including the
// dynamic style's lens that follows the cursor and its group order kept across frames.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "renderer/scene/scene_source.hpp"
#include "stimuli/scenes/stimulus_scenes.hpp"
#include "study/run/frame_log.hpp"
#include "study/run/live_view.hpp"
#include "study/run/stimulus_library.hpp"
#include "tests/support/gl_fixture.hpp"

namespace tlab::study {
namespace {

struct Fixture {
  std::shared_ptr<const render::Scene> scene;
  StimulusKey key;
  render::Camera start;
};

Fixture lensFixture() {
  Fixture f;
  f.key.scene = "builtin:abstract?seed=3";
  f.key.style = "dynamic";
  f.key.renderSettings = {"mode=active", "lens_radius=0.3"};
  f.key.width = f.key.height = 96;
  f.scene = loadStimulusScene(f.key, stimuli::allSceneSpecs());
  f.start = stimulusCamera(*f.scene, f.key);
  return f;
}

struct Shown {
  render::Camera camera;
  std::optional<glm::vec2> lens;
  std::string sha256;
};

Shown shown(LiveView& view) {
  const std::string sha = framePixelsSha256(view.frame());
  return {view.rendered().camera, view.rendered().lens, sha};
}

TEST(LiveViewReplay, LoggedCamerasAndLensesRenderTheSamePixelsAgainInOrder) {
  const Fixture f = lensFixture();
  LiveView live(f.scene, f.key, Navigation::Orbit, f.start);
  std::vector<Shown> log;
  log.push_back(shown(live));
  EXPECT_FALSE(log.back().lens) << "no lens before the cursor is over the picture";
  ASSERT_TRUE(live.pointAt({0.3f, 0.6f}));
  log.push_back(shown(live));
  live.navigator().drag(40.0, 10.0);
  log.push_back(shown(live));
  ASSERT_TRUE(live.pointAt({1.7f, -0.2f}));  // outside: clamped to the picture's corner
  log.push_back(shown(live));
  live.navigator().move(1, 0);
  log.push_back(shown(live));
  EXPECT_EQ(live.rendered().count, 5);
  ASSERT_TRUE(log[3].lens);
  EXPECT_EQ(*log[3].lens, glm::vec2(1.0f, 0.0f));
  for (std::size_t i = 1; i < log.size(); ++i) EXPECT_NE(log[i].sha256, log[i - 1].sha256) << "frame " << i << " shows no change";

  LiveView replay(f.scene, f.key, Navigation::Orbit, f.start);
  for (std::size_t i = 0; i < log.size(); ++i)
    EXPECT_EQ(framePixelsSha256(replay.frameFrom(log[i].camera, log[i].lens)), log[i].sha256) << "frame " << i;
}

TEST(LiveViewReplay, NoLensIsTheStyleSettingsOwnLensAgain) {
  const Fixture f = lensFixture();
  LiveView fresh(f.scene, f.key, Navigation::Orbit, f.start);
  const std::string before = framePixelsSha256(fresh.frame());
  LiveView moved(f.scene, f.key, Navigation::Orbit, f.start);
  const std::string lensed = framePixelsSha256(moved.frameFrom(f.start, glm::vec2(0.8f, 0.8f)));
  EXPECT_NE(lensed, before);
  EXPECT_EQ(framePixelsSha256(moved.frameFrom(f.start, std::nullopt)), before);
}

TEST(LiveViewReplay, AViewWhoseLensDoesNotFollowTheCursorIgnoresPointing) {
  Fixture f = lensFixture();
  f.key.style = "constant";
  f.key.renderSettings = {};
  LiveView view(f.scene, f.key, Navigation::Orbit, f.start);
  EXPECT_FALSE(view.pointAt({0.5f, 0.5f}));
  const std::string first = framePixelsSha256(view.frame());
  EXPECT_FALSE(view.rendered().lens);
  EXPECT_EQ(framePixelsSha256(view.frameFrom(f.start, glm::vec2(0.2f, 0.2f))), first);
}

}  // namespace
}  // namespace tlab::study
