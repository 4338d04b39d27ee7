// The shape tasks: the gauge figure's normals against the sphere's analytic normals, its score
// against analytic angles, the answer form's round trips, and relative depth against depths
// computed here from the camera.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/scene/scene_source.hpp"
#include "tasks/answer_form.hpp"
#include "tasks/answer_parser.hpp"
#include "tasks/gauge_figure/gauge_figure_task.hpp"
#include "tasks/gauge_frame.hpp"
#include "tasks/relative_depth/relative_depth_task.hpp"
#include "tasks/scoring.hpp"

namespace tlab::tasks {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Spheres {
  render::Scene scene = render::loadScene("builtin:nested-spheres?n=3");
  render::Camera camera = render::fitCamera(scene.boundingSphere(), 1.0f, 45.0f, {0.3f, 0.4f, 1.0f});
};

double measurement(const Question& q, const std::string& key) {
  for (const auto& [k, v] : q.measurements)
    if (k == key) return v;
  ADD_FAILURE() << "no measurement " << key;
  return 0.0;
}

// The spheres are centred at the origin: the true normal at p is ±p/|p|, the sign facing the eye.
void expectRadialFacingTheEye(const Question& q, glm::dvec3 eye) {
  const glm::dvec3 p = q.points.at(0).world, n = std::get<glm::dvec3>(q.truth);
  const glm::dvec3 radial = glm::normalize(p) * (glm::dot(glm::normalize(p), eye - p) > 0.0 ? 1.0 : -1.0);
  EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
  EXPECT_LT(glm::length(n - radial), 1e-6) << "question " << q.number;
  EXPECT_GT(glm::dot(n, eye - p), 0.0);
}

TEST(GaugeFigure, FrontNormalsAreTheSpheresRadiiFacingTheViewer) {
  const Spheres s;
  const GaugeFigureTask task;
  const auto questions = task.probe({s.scene, s.camera, 400, 400, 6, 3, task.settings({})});
  ASSERT_EQ(questions.size(), 6u);
  for (const auto& q : questions) {
    EXPECT_EQ(q.answerKind, AnswerKind::Direction);
    expectRadialFacingTheEye(q, glm::dvec3(s.camera.eye));
    // On the front surface of the outer shell (radius 1) the normal points outwards, towards the eye.
    EXPECT_NEAR(glm::length(q.points[0].world), 1.0, 2e-3);
    EXPECT_GT(glm::dot(std::get<glm::dvec3>(q.truth), glm::normalize(q.points[0].world)), 0.999999);
    EXPECT_LE(measurement(q, "slant"), 75.0);
  }
}

TEST(GaugeFigure, DeeperLayersAreInnerShellsOrTheBackFacingTheViewer) {
  const Spheres s;
  const GaugeFigureTask task;
  const auto questions = task.probe({s.scene, s.camera, 400, 400, 6, 9, task.settings({"layer=2"})});
  for (const auto& q : questions) {
    expectRadialFacingTheEye(q, glm::dvec3(s.camera.eye));
    EXPECT_EQ(measurement(q, "layer"), 2.0);
    // Layer 2 is the front of the middle shell (radius 2/3) or, outside it, the back of the outer one.
    const double r = glm::length(q.points[0].world);
    EXPECT_TRUE(std::abs(r - 2.0 / 3.0) < 2e-3 || std::abs(r - 1.0) < 2e-3) << r;
  }
}

TEST(GaugeFigure, SlantAndTiltDescribeTheTruthInTheView) {
  const Spheres s;
  const GaugeFigureTask task;
  const ViewGeometry view(s.camera, 400, 400);
  for (const auto& q : task.probe({s.scene, s.camera, 400, 400, 4, 11, task.settings({})})) {
    const GaugeFrame f = gaugeFrameOf(q);
    EXPECT_NEAR(glm::dot(f.w, glm::normalize(view.eye() - q.points[0].world)), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(f.u, f.w), 0.0, 1e-12);
    const glm::dvec3 n = normalFromSlantTilt(f, measurement(q, "slant"), measurement(q, "tilt"));
    EXPECT_LT(glm::length(n - std::get<glm::dvec3>(q.truth)), 1e-9);
  }
}

TEST(GaugeFigure, ScoreIsTheAngleToTheTruthWithSlantAndTiltErrors) {
  const Spheres s;
  const GaugeFigureTask task;
  const Question q = task.probe({s.scene, s.camera, 400, 400, 1, 3, task.settings({})}).at(0);
  const AnswerForm& form = answerForm(q);
  const double slant = measurement(q, "slant"), tilt = measurement(q, "tilt");
  // The truth itself, given by the gauge: error 0 (to the 6 decimals of the text form).
  const std::string exact = form.fromInput(q, GaugeSetting{slant, tilt});
  const Score right = task.score(q, {exact, 5.0});
  EXPECT_TRUE(right.correct);
  EXPECT_NEAR(*right.error, 0.0, 1e-3);
  // 20° more slant at the same tilt: the angle is 20°, the slant error +20, the tilt error 0.
  const Score steeper = task.score(q, {form.fromInput(q, GaugeSetting{slant + 20.0, tilt}), 5.0});
  EXPECT_NEAR(*steeper.error, 20.0, 1e-3);
  EXPECT_FALSE(steeper.correct);  // correct within 15°
  ASSERT_EQ(steeper.measures.size(), 2u);
  EXPECT_NEAR(steeper.measures[0].second, 20.0, 1e-3);
  EXPECT_NEAR(steeper.measures[1].second, 0.0, 1e-3);
  // Typed in any length, a direction is the same answer.
  const glm::dvec3 n = std::get<glm::dvec3>(q.truth) * 3.5;
  EXPECT_NEAR(*task.score(q, {std::to_string(n.x) + ", " + std::to_string(n.y) + "," + std::to_string(n.z), 5.0}).error, 0.0, 1e-3);
  EXPECT_THROW(task.score(q, {"0,0,0", 5.0}), AnswerFormatError);
  EXPECT_THROW(task.score(q, {"1,2", 5.0}), AnswerFormatError);
  EXPECT_THROW(form.fromInput(q, GaugeSetting{95.0, 0.0}), AnswerFormatError);
  // A missing answer has no angle.
  EXPECT_FALSE(task.score(q, {std::nullopt, std::nullopt}).error.has_value());
}

// A simulated observer who knows: the truth tilted by a Gaussian tangent offset of angular sd
// σ = gauge_degrees (1 + gauge_growth (1 − v)); the mean angle of such an offset is about σ √(π/2)
// (the mean of a Rayleigh distribution), and it grows as the visibility v falls.
TEST(GaugeFigure, SimulatedErrorsFollowTheDocumentedAngularNoise) {
  const Spheres s;
  const GaugeFigureTask task;
  const Question q = task.probe({s.scene, s.camera, 400, 400, 1, 3, task.settings({"max-slant=30"})}).at(0);
  const AnswerForm& form = answerForm(q);
  const AnswerNoise noise{4.0, 3.0};
  const auto meanError = [&](double visibility) {
    core::SeededRandom random(99);
    double sum = 0.0;
    for (int i = 0; i < 4000; ++i) sum += angleDegrees(parseDirection(form.known(q, random, visibility, noise)), std::get<glm::dvec3>(q.truth));
    return sum / 4000;
  };
  const double seen = meanError(1.0), faint = meanError(0.0);
  EXPECT_NEAR(seen, 4.0 * std::sqrt(kPi / 2.0), 0.2);
  EXPECT_NEAR(faint, 16.0 * std::sqrt(kPi / 2.0), 1.2);  // tan compresses large angles a little
  EXPECT_GT(faint, 3.0 * seen);
}

TEST(GaugeFrame, SlantTiltRoundTripsAndAnglesAreExact) {
  const GaugeFrame f{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const glm::dvec3 n = normalFromSlantTilt(f, 30.0, 120.0);
  EXPECT_NEAR(n.x, std::sin(kPi / 6) * std::cos(2 * kPi / 3), 1e-15);
  EXPECT_NEAR(n.z, std::cos(kPi / 6), 1e-15);
  const glm::dvec2 st = slantTiltOf(f, n);
  EXPECT_NEAR(st.x, 30.0, 1e-12);
  EXPECT_NEAR(st.y, 120.0, 1e-12);
  EXPECT_NEAR(angleDegrees({1, 0, 0}, {1, 1e-9, 0}), 1e-9 * 180.0 / kPi, 1e-20);
  EXPECT_NEAR(tiltDifference(350.0, 10.0), -20.0, 1e-12);
  EXPECT_NEAR(tiltDifference(10.0, 350.0), 20.0, 1e-12);
}

TEST(GaugeFigure, WidgetStartsAtTheLoggedSeededOrientation) {
  const Spheres s;
  const GaugeFigureTask task;
  const auto a = task.probe({s.scene, s.camera, 400, 400, 2, 21, task.settings({})});
  const auto b = task.probe({s.scene, s.camera, 400, 400, 2, 21, task.settings({})});
  const Widget w = answerForm(a[1]).widget(a[1]);
  EXPECT_EQ(w.kind, WidgetKind::Gauge);
  EXPECT_EQ(w.startSlant, measurement(b[1], "start-slant"));
  EXPECT_EQ(w.startTilt, measurement(b[1], "start-tilt"));
  EXPECT_EQ(w.at, a[1].points[0].pixel);
  EXPECT_FALSE(answerForm(a[1]).bookletField().has_value());  // a gauge cannot be printed
}

TEST(GaugeFigure, OnACubeTheTruthIsAFaceNormalAndGaugesNeverStraddleAnEdge) {
  const render::Scene scene = render::loadScene("builtin:cube");
  const render::Camera camera = render::fitCamera(scene.boundingSphere(), 1.0f);
  const GaugeFigureTask task;
  for (const auto& q : task.probe({scene, camera, 300, 300, 4, 2, task.settings({"min-separation-px=10"})})) {
    const glm::dvec3 n = std::get<glm::dvec3>(q.truth);
    EXPECT_NEAR(std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)}), 1.0, 1e-6);
    EXPECT_EQ(q.checks.at(1).value, 0.0);  // every rim point of the gauge on the same flat face
  }
  // A gauge wider than any face has nowhere to lie: the edges are creases.
  EXPECT_THROW(task.probe({scene, camera, 200, 200, 1, 1, task.settings({"gauge-radius-px=90", "attempts=300"})}), std::runtime_error);
}

TEST(RelativeDepth, TruthIsTheLabelOfThePointNearerAlongTheViewingDirection) {
  const Spheres s;
  const RelativeDepthTask task;
  const glm::dvec3 eye(s.camera.eye), forward = glm::normalize(glm::dvec3(s.camera.target) - eye);
  for (const auto* layers : {"layer-b=1", "layer-b=3"}) {
    const auto questions = task.probe({s.scene, s.camera, 400, 400, 5, 4, task.settings({layers})});
    ASSERT_EQ(questions.size(), 5u);
    for (const auto& q : questions) {
      ASSERT_EQ(q.points.size(), 2u);
      const double a = glm::dot(q.points[0].world - eye, forward), b = glm::dot(q.points[1].world - eye, forward);
      EXPECT_EQ(std::get<std::string>(q.truth), a < b ? "A" : "B");
      EXPECT_GE(std::abs(a - b), 0.05 * 2.0 * s.scene.boundingSphere().radius);
      EXPECT_EQ(answerForm(q).widget(q).kind, WidgetKind::PickLabel);
      EXPECT_TRUE(scoreAnswer(q, {std::get<std::string>(q.truth), 1.0}).correct);
    }
  }
}

TEST(RelativeDepth, RefusesWhenNoPairDiffersEnoughInDepth) {
  const Spheres s;
  const RelativeDepthTask task;
  EXPECT_THROW(task.probe({s.scene, s.camera, 300, 300, 1, 1, task.settings({"min-depth-gap=1", "attempts=100"})}), std::runtime_error);
}

}  // namespace
}  // namespace tlab::tasks
