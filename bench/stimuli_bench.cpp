// Google Benchmark: particle integration per method and the advancing front of the flow surfaces.
// (Error vs. time per tolerance is `tlab bench integrate`.)
#include <benchmark/benchmark.h>

#include "stimuli/fields/abc_flow.hpp"
#include "stimuli/fields/stiff_relaxation_field.hpp"
#include "stimuli/fields/vortex_ring.hpp"
#include "stimuli/integration/particle_integrator.hpp"
#include "stimuli/scenes/flow_surface_scenes.hpp"
#include "stimuli/surfaces/advancing_front.hpp"

namespace {

using namespace tlab::stimuli;

void integrate(benchmark::State& state, const VectorField& field, IntegratorKind kind, double stepOrTolerance) {
  IntegratorSettings s;
  s.kind = kind;
  s.step = kind == IntegratorKind::RungeKutta4 ? stepOrTolerance : 1e-3;
  s.absoluteTolerance = s.relativeTolerance = stepOrTolerance;
  const ParticleIntegrator integrator(field, s);
  std::size_t steps = 0;
  for (auto _ : state) {
    const ParticleAdvance a = integrator.advance(glm::dvec3(0.4, 0.3, 0.2), 0.0, 5.0);
    benchmark::DoNotOptimize(a.position);
    steps += a.steps;
  }
  state.counters["steps"] = benchmark::Counter(double(steps), benchmark::Counter::kAvgIterations);
}

void BM_AbcRk4(benchmark::State& state) { integrate(state, AbcFlow(), IntegratorKind::RungeKutta4, 0.01); }
void BM_AbcDopri5(benchmark::State& state) { integrate(state, AbcFlow(), IntegratorKind::DormandPrince, 1e-7); }
void BM_AbcRosenbrock4(benchmark::State& state) { integrate(state, AbcFlow(), IntegratorKind::Rosenbrock4, 1e-7); }
void BM_StiffDopri5(benchmark::State& state) { integrate(state, StiffRelaxationField(), IntegratorKind::DormandPrince, 1e-7); }
void BM_StiffRosenbrock4(benchmark::State& state) { integrate(state, StiffRelaxationField(), IntegratorKind::Rosenbrock4, 1e-7); }

void BM_VortexRingStreamSurface(benchmark::State& state) {
  const VortexRing ring;
  IntegratorSettings s;
  s.absoluteTolerance = s.relativeTolerance = 1e-7;
  AdvancingFrontSettings f;
  f.maxSpacing = 0.05;
  f.minSpacing = 0.015;
  f.steps = int(state.range(0));
  f.timeStep = 0.025;
  std::size_t triangles = 0;
  for (auto _ : state) {
    const IntegralSurface surface = streamSurface(ring, SeedCurve::line({0.7, 0.0, 0.0}, {1.3, 0.0, 0.0}), 0.0, s, f);
    triangles = surface.mesh.triangleCount();
    benchmark::DoNotOptimize(surface.mesh.positions.data());
  }
  state.counters["triangles"] = double(triangles);
}

void BM_FlowSurfaceScene(benchmark::State& state) {
  const FlowSurfaceParams p;
  for (auto _ : state) {
    const auto scene = state.range(0) == 0 ? pretzelScene(p) : state.range(0) == 1 ? bubbleScene(p) : toroidScene(p);
    benchmark::DoNotOptimize(scene.objects.data());
  }
}

BENCHMARK(BM_AbcRk4);
BENCHMARK(BM_AbcDopri5);
BENCHMARK(BM_AbcRosenbrock4);
BENCHMARK(BM_StiffDopri5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StiffRosenbrock4);
BENCHMARK(BM_VortexRingStreamSurface)->Arg(40)->Arg(160)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FlowSurfaceScene)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace
