// Integrators against closed-form trajectories (solid rotation, linear saddle, the stiff field),
// and Rosenbrock4's advantage on the stiff field.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "stimuli/fields/abc_flow.hpp"
#include "stimuli/fields/double_gyre.hpp"
#include "stimuli/fields/field_registry.hpp"
#include "stimuli/fields/linear_saddle.hpp"
#include "stimuli/fields/solid_rotation.hpp"
#include "stimuli/fields/stiff_relaxation_field.hpp"
#include "stimuli/integration/particle_integrator.hpp"

namespace tlab::stimuli {
namespace {

IntegratorSettings adaptive(IntegratorKind kind, double tolerance) {
  IntegratorSettings s;
  s.kind = kind;
  s.step = 1e-3;
  s.absoluteTolerance = s.relativeTolerance = tolerance;
  return s;
}

IntegratorSettings fixedStep(double h) {
  IntegratorSettings s;
  s.kind = IntegratorKind::RungeKutta4;
  s.step = h;
  return s;
}

TEST(ParticleIntegrator, Rk4ConvergesAtFourthOrderOnSolidRotation) {
  const SolidRotation field(1.0);
  const glm::dvec3 x0(1.0, 0.0, 0.3);
  const double t1 = 2.0 * std::numbers::pi;
  const glm::dvec3 exact = field.exactPosition(x0, 0.0, t1);
  const double coarse = glm::distance(ParticleIntegrator(field, fixedStep(0.1)).advance(x0, 0.0, t1).position, exact);
  const double fine = glm::distance(ParticleIntegrator(field, fixedStep(0.05)).advance(x0, 0.0, t1).position, exact);
  EXPECT_LT(fine, 1e-5);
  EXPECT_NEAR(std::log2(coarse / fine), 4.0, 0.3);  // halving h divides the error by 2⁴
}

TEST(ParticleIntegrator, AdaptiveMethodsMeetTheirToleranceOnClosedFormFields) {
  const SolidRotation rotation(1.3);
  const LinearSaddle saddle(1.0, -0.5);
  const glm::dvec3 x0(0.7, -0.4, 0.5);
  for (const auto kind : {IntegratorKind::DormandPrince, IntegratorKind::Rosenbrock4})
    for (const double tol : {1e-4, 1e-6, 1e-8}) {
      const double e1 = glm::distance(ParticleIntegrator(rotation, adaptive(kind, tol)).advance(x0, 0.0, 5.0).position,
                                      rotation.exactPosition(x0, 0.0, 5.0));
      const glm::dvec3 exactSaddle = saddle.exactPosition(x0, 0.0, 2.0);
      const double e2 = glm::distance(ParticleIntegrator(saddle, adaptive(kind, tol)).advance(x0, 0.0, 2.0).position, exactSaddle) /
                        glm::length(exactSaddle);
      // Local error control: the global error stays within a modest multiple of the tolerance.
      EXPECT_LT(e1, 50.0 * tol) << integratorName(kind) << " tol " << tol;
      EXPECT_LT(e2, 50.0 * tol) << integratorName(kind) << " tol " << tol;
    }
}

TEST(ParticleIntegrator, TighterToleranceGivesSmallerErrorAndMoreSteps) {
  const LinearSaddle saddle;
  const glm::dvec3 x0(0.5, 0.5, 0.5);
  const auto loose = ParticleIntegrator(saddle, adaptive(IntegratorKind::DormandPrince, 1e-4)).advance(x0, 0.0, 3.0);
  const auto tight = ParticleIntegrator(saddle, adaptive(IntegratorKind::DormandPrince, 1e-9)).advance(x0, 0.0, 3.0);
  const glm::dvec3 exact = saddle.exactPosition(x0, 0.0, 3.0);
  EXPECT_LT(glm::distance(tight.position, exact), glm::distance(loose.position, exact));
  EXPECT_GT(tight.steps, loose.steps);
}

TEST(ParticleIntegrator, BackwardIntegrationReturnsToTheStart) {
  const AbcFlow abc;
  const ParticleIntegrator integrator(abc, adaptive(IntegratorKind::DormandPrince, 1e-10));
  const glm::dvec3 x0(0.1, 0.2, 0.3);
  const glm::dvec3 x1 = integrator.advance(x0, 0.0, 2.0).position;
  EXPECT_LT(glm::distance(integrator.advance(x1, 2.0, 0.0).position, x0), 1e-7);
}

TEST(StiffRelaxationField, HasStiffnessRatioAtLeast1e4AndAnExactJacobian) {
  const StiffRelaxationField field;
  EXPECT_GE(field.stiffnessRatio(), 1e4);
  const glm::dvec3 p(0.3, -0.7, 0.2);
  const glm::dmat3 exact = field.jacobian(p, 0.0);
  const glm::dmat3 numeric = field.VectorField::jacobian(p, 0.0);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(exact[c][r], numeric[c][r], 1e-4 * (1.0 + std::abs(exact[c][r])));
}

// Rosenbrock4 reaches a given accuracy on the stiff field with ≥ 100× fewer steps than RK4, whose
// step is bounded by stability (λ h ≲ 2.8) rather than by accuracy.
TEST(StiffRelaxationField, Rosenbrock4TakesAHundredTimesFewerStepsThanRk4AtEqualAccuracy) {
  const StiffRelaxationField field;
  const glm::dvec3 x0(1.0, 0.0, 0.5);
  const double t1 = 2.0 * std::numbers::pi;
  const glm::dvec3 exact = field.exactPosition(x0, 0.0, t1);
  const auto rosenbrock = ParticleIntegrator(field, adaptive(IntegratorKind::Rosenbrock4, 1e-6)).advance(x0, 0.0, t1);
  const double accuracy = glm::distance(rosenbrock.position, exact);
  ASSERT_LT(accuracy, 1e-4);
  // The largest RK4 step (on a fine ladder) that reaches the same accuracy.
  std::size_t rk4Steps = 0;
  for (double h = 1e-2; h > 1e-6; h *= 0.9) {
    const auto rk4 = ParticleIntegrator(field, fixedStep(h)).advance(x0, 0.0, t1);
    if (glm::distance(rk4.position, exact) <= accuracy) {
      rk4Steps = rk4.steps;
      break;
    }
  }
  ASSERT_GT(rk4Steps, 0u);
  EXPECT_GE(double(rk4Steps), 100.0 * double(rosenbrock.steps)) << "rk4 " << rk4Steps << " rosenbrock4 " << rosenbrock.steps;
}

// A time-dependent field with a closed form: v = (cos t, −x sin t ... ) kept simple: v = (cos t, x, 0)
// gives x = x0 + sin t − sin t0 and y = y0 + ∫ x dt.
class OscillatingShear final : public VectorField {
 public:
  std::string name() const override { return "oscillating-shear"; }
  bool steady() const override { return false; }
  FieldDomain domain() const override { return {glm::dvec3(-100.0), glm::dvec3(100.0)}; }
  glm::dvec3 velocity(const glm::dvec3& p, double t) const override { return {std::cos(t), p.x, 0.0}; }
  static glm::dvec3 exact(const glm::dvec3& p0, double t1) {  // from t0 = 0
    return {p0.x + std::sin(t1), p0.y + p0.x * t1 + 1.0 - std::cos(t1), p0.z};
  }
};

TEST(ParticleIntegrator, EveryMethodFollowsATimeDependentClosedForm) {
  const OscillatingShear field;
  const glm::dvec3 x0(0.3, -0.2, 0.1);
  const glm::dvec3 exact = OscillatingShear::exact(x0, 6.0);
  EXPECT_LT(glm::distance(ParticleIntegrator(field, fixedStep(0.01)).advance(x0, 0.0, 6.0).position, exact), 1e-8);
  for (const auto kind : {IntegratorKind::DormandPrince, IntegratorKind::Rosenbrock4})
    EXPECT_LT(glm::distance(ParticleIntegrator(field, adaptive(kind, 1e-8)).advance(x0, 0.0, 6.0).position, exact), 1e-6)
        << integratorName(kind);
}

TEST(DoubleGyre, AnalyticDerivativesMatchFiniteDifferences) {
  const DoubleGyre gyre;
  for (const double t : {0.0, 1.3, 4.0}) {
    const glm::dvec3 p(0.7, 0.35, 0.0);
    const glm::dmat3 exact = gyre.jacobian(p, t), numeric = gyre.VectorField::jacobian(p, t);
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) EXPECT_NEAR(exact[c][r], numeric[c][r], 1e-6);
    const glm::dvec3 dt = gyre.timeDerivative(p, t), numericDt = gyre.VectorField::timeDerivative(p, t);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(dt[i], numericDt[i], 1e-6);
  }
}

TEST(FieldRegistry, BuildsEveryNamedFieldAndRejectsUnknownNames) {
  for (const auto& name : vectorFieldNames()) {
    const auto field = makeVectorField(name);
    EXPECT_EQ(field->name(), name);
    const glm::dvec3 v = field->velocity(glm::dvec3(0.3, 0.4, 0.5), 0.7);
    EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) << name;
  }
  EXPECT_THROW(makeVectorField("nope"), std::invalid_argument);
}

// The axisymmetric model fields are divergence-free (they come from Stokes stream functions).
TEST(VectorFields, ModelFlowsAreDivergenceFree) {
  for (const char* name : {"vortex-ring", "swirling-jet", "hills-vortex", "abc", "double-gyre"}) {
    const auto field = makeVectorField(name);
    for (const glm::dvec3 p : {glm::dvec3(0.3, 0.4, 0.2), glm::dvec3(1.1, -0.2, 0.3), glm::dvec3(0.5, 0.6, -0.7)}) {
      const glm::dmat3 j = field->jacobian(p, 0.4);
      EXPECT_NEAR(j[0][0] + j[1][1] + j[2][2], 0.0, 1e-5) << name;
    }
  }
}

}  // namespace
}  // namespace tlab::stimuli
