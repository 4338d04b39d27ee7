// The simulated observer: what the stimulus shows at the probes drives accuracy and response
// time (high local contrast → knows the answer and answers fast; a flat image → guesses slowly),
// its answers parse as the task's answer kind, and it is deterministic per participant and trial.
#include <gtest/gtest.h>

#include "study/run/image_contrast.hpp"
#include "study/run/simulated_observer.hpp"
#include "tasks/answer_parser.hpp"

using namespace tlab::study;

namespace {

PreparedTrial layerTrial(const tlab::core::Image& picture) {
  PreparedTrial p;
  p.picture = std::make_shared<tlab::core::Image>(picture);
  p.question.task = "layer-index";
  p.question.answerKind = tlab::tasks::AnswerKind::LayerNumber;
  p.question.truth = std::int64_t(1);
  p.question.points = {{"A", "probe", glm::dvec3(0), glm::dvec2(32.5, 32.5), 0}};
  return p;
}

tlab::core::Image checkerboard() {
  tlab::core::Image image(64, 64, glm::vec4(1));
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      if ((x / 2 + y / 2) % 2) image.at(x, y) = glm::vec4(0, 0, 0, 1);
  return image;
}

double accuracy(const PreparedTrial& prepared, double* meanSeconds) {
  int correct = 0, answered = 0;
  double seconds = 0;
  for (int participant = 0; participant < 200; ++participant) {
    SimulatedObserver observer(ObserverParams{}, 11, "p" + std::to_string(participant));
    PlannedTrial plan;
    plan.sequence = 1;
    const ObserverDecision d = observer.decide({plan, prepared, 600.0, 1, 1});
    if (!d.answer) continue;
    ++answered;
    seconds += d.seconds;
    correct += tlab::tasks::parseLayerNumber(*d.answer) == 1 ? 1 : 0;
  }
  *meanSeconds = seconds / answered;
  return double(correct) / answered;
}

}  // namespace

TEST(ImageContrast, LocalRmsContrastOfLuminance) {
  EXPECT_DOUBLE_EQ(localRmsContrast(tlab::core::Image(16, 16, glm::vec4(0.3f, 0.3f, 0.3f, 1)), {8, 8}), 0.0);
  EXPECT_NEAR(localRmsContrast(checkerboard(), {32.5, 32.5}), 0.5, 0.02);  // half black, half white
  EXPECT_EQ(localRmsContrast(checkerboard(), {-3, 10}), 0.0);
}

TEST(SimulatedObserver, AccuracyAndSpeedFollowWhatTheStimulusShows) {
  double fastSeconds = 0, slowSeconds = 0;
  const double visible = accuracy(layerTrial(checkerboard()), &fastSeconds);
  const double flat = accuracy(layerTrial(tlab::core::Image(64, 64, glm::vec4(0.5f, 0.5f, 0.5f, 1))), &slowSeconds);
  EXPECT_GT(visible, 0.85);
  EXPECT_LT(flat, 0.55);  // mostly guesses among 1..3
  EXPECT_LT(fastSeconds, slowSeconds);
}

TEST(SimulatedObserver, DeterministicPerParticipantAndTrial) {
  const PreparedTrial prepared = layerTrial(checkerboard());
  PlannedTrial plan;
  plan.sequence = 5;
  SimulatedObserver a(ObserverParams{}, 3, "x"), b(ObserverParams{}, 3, "x"), c(ObserverParams{}, 3, "y");
  const auto da = a.decide({plan, prepared, 60.0, 5, 9}), db = b.decide({plan, prepared, 60.0, 5, 9});
  EXPECT_EQ(da.answer, db.answer);
  EXPECT_EQ(da.seconds, db.seconds);
  EXPECT_NE(a.skill(), c.skill());
  const auto r = a.respond({plan, prepared, 0.001, 5, 9});  // far too little time: missing
  ASSERT_TRUE(r);
  EXPECT_FALSE(r->text);
  EXPECT_FALSE(r->rtSeconds);
}
