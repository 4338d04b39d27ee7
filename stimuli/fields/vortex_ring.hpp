#pragma once
// A swirling vortex ring of radius R in the plane z = 0, axis z, seen in its own frame: the flow
// circulates about the core circle with a Gaussian core (radius a; at the core the angular speed of
// a Lamb–Oseen vortex of circulation Γ, Ω = Γ/(2π a²)), the outer fluid streams past along z, a
// uniform stream U may be added, and the core swirls along the ring (strength S). Built from a
// Stokes stream function, so it is divergence-free. Stream surfaces through the core roll up into
// tubes.
#include "stimuli/fields/vector_field.hpp"

namespace tlab::stimuli {

struct VortexRingParams {
  double ringRadius = 1.0;     // R
  double coreRadius = 0.35;    // a
  double circulation = 4.0;    // Γ
  double travelSpeed = 0.0;    // U
  double swirl = 0.6;          // S: velocity along the core at its centre
  double extent = 4.0;         // the domain is [−extent, extent]³
};

class VortexRing final : public VectorField {
 public:
  explicit VortexRing(VortexRingParams p = {}) : p_(p) {}
  std::string name() const override { return "vortex-ring"; }
  bool steady() const override { return true; }
  FieldDomain domain() const override { return {glm::dvec3(-p_.extent), glm::dvec3(p_.extent)}; }
  glm::dvec3 velocity(const glm::dvec3& x, double t) const override;

 private:
  VortexRingParams p_;
};

}  // namespace tlab::stimuli
