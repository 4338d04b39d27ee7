#pragma once
// Integral surfaces by an advancing front (Hultquist 1992, as in IRIS Sec. 2): the seed curve's
// particles are advanced in steps of Δt; between two consecutive fronts a strip of triangles is
// stitched on the fly. Where neighbouring particles diverge (spacing > maxSpacing) or the front
// bends (angle > maxBend, Garth et al. 2004's curvature criterion) particles are inserted — seeded
// on the previous front at the mid parameter and integrated forward — and where they converge
// (spacing < minSpacing) particles are removed. Each vertex carries (s, t): s along the seed curve,
// t the integration time since seeding (IRIS Sec. 2). Where refinement cannot keep up (particle
// budget, s resolution) and neighbours drift apart beyond tearFactor·maxSpacing, the front tears
// instead of spanning the gap with long triangles.
#include <cstdint>
#include <vector>

#include "renderer/scene/triangle_mesh.hpp"
#include "stimuli/integration/particle_integrator.hpp"
#include "stimuli/surfaces/seed_curve.hpp"

namespace tlab::stimuli {

struct AdvancingFrontSettings {
  double timeStep = 0.05;         // Δt between fronts
  int steps = 100;                // number of fronts after the seed front
  double maxSpacing = 0.05;       // world units: insert above this
  double minSpacing = 0.015;      // world units: remove below this
  double maxBendDegrees = 25.0;   // Garth: refine where the front turns more sharply
  double minParameterGap = 1e-5;  // no insertion between particles closer than this in s
  std::size_t maxParticles = 3000;  // per front; refinement stops beyond it
  double tearFactor = 4.0;        // the front tears where neighbours drift farther than tearFactor·maxSpacing
};

// How the front looked after one advance (for the resolution tests and diagnostics).
struct FrontStatistics {
  int step = 0;
  std::size_t particles = 0;
  std::size_t runs = 0;           // pieces the front has torn into (particles leaving the domain)
  double minSpacing = 0.0;        // smallest neighbour distance
  double maxSpacing = 0.0;        // largest neighbour distance
  std::size_t inserted = 0, removed = 0;
};

struct IntegralSurface {
  render::TriangleMesh mesh;                          // positions, normals, st = (s, t)
  std::vector<std::vector<std::uint32_t>> tracks;     // per particle: its vertices, in time order
  std::vector<FrontStatistics> fronts;
  std::size_t integratorSteps = 0;
};

class AdvancingFront {
 public:
  AdvancingFront(const ParticleIntegrator& integrator, AdvancingFrontSettings settings)
      : integrator_(integrator), settings_(settings) {}
  // Sweeps the surface seeded on `seed` at time t0.
  IntegralSurface sweep(const SeedCurve& seed, double t0) const;

 private:
  const ParticleIntegrator& integrator_;
  AdvancingFrontSettings settings_;
};

// A stream surface of the field frozen at t0 (IRIS Sec. 2).
IntegralSurface streamSurface(const VectorField& field, const SeedCurve& seed, double t0, const IntegratorSettings& integrator,
                              const AdvancingFrontSettings& front);
// A path surface: particles follow v(x, t) (IRIS Sec. 2).
IntegralSurface pathSurface(const VectorField& field, const SeedCurve& seed, double t0, const IntegratorSettings& integrator,
                            const AdvancingFrontSettings& front);

}  // namespace tlab::stimuli
