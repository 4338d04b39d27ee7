#pragma once
// A swirling jet along z with a vortex-breakdown bubble: Stokes stream function
//   ψ(r, z) = r²/2 · (W − A e^{−(r² + (z − z_b)²)/σ²}),
// v_r = −(1/r) ∂ψ/∂z, v_z = (1/r) ∂ψ/∂r (divergence-free), plus Burgers-like swirl
// v_φ = S r e^{−r²/σ_s²}. For A > W the axial velocity reverses near z_b: a recirculation bubble
// bounded by two stagnation points on the axis.
#include "stimuli/fields/vector_field.hpp"

namespace tlab::stimuli {

struct SwirlingJetParams {
  double axialSpeed = 1.0;       // W
  double bubbleStrength = 2.2;   // A
  double bubbleCenter = 0.0;     // z_b
  double bubbleWidth = 0.7;      // σ
  double swirl = 2.5;            // S
  double swirlWidth = 0.8;       // σ_s
};

class SwirlingJet final : public VectorField {
 public:
  explicit SwirlingJet(SwirlingJetParams p = {}) : p_(p) {}
  std::string name() const override { return "swirling-jet"; }
  bool steady() const override { return true; }
  FieldDomain domain() const override { return {glm::dvec3(-3.0, -3.0, -3.0), glm::dvec3(3.0, 3.0, 3.0)}; }
  glm::dvec3 velocity(const glm::dvec3& x, double t) const override;

 private:
  SwirlingJetParams p_;
};

}  // namespace tlab::stimuli
