#include "bench/measure/diffusion_frame.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "renderer/gpu/gl.hpp"
#include "renderer/ops/connect_pass.hpp"
#include "renderer/ops/diffusion_solver.hpp"
#include "renderer/styles/smart_style.hpp"

namespace tlab::bench {

DiffusionFrame::DiffusionFrame(render::Scene s, int w, int h)
    : scene(std::move(s)), gpu(scene), radius(scene.boundingSphere().radius) {
  const render::SmartStyle style;
  const auto params = style.resolve({});
  buffer = std::make_unique<render::FragmentBuffer>(shaders, w, h, render::FragmentLayout(style.properties(params, {gpu.componentCount()})),
                                                    render::FillMethod::CountScatter);
  const render::Camera camera = scene.camera ? *scene.camera : render::fitCamera(scene.boundingSphere(), float(w) / float(h));
  render::RasterUniforms u;
  u.view = camera.view();
  u.projection = camera.projection(float(w) / float(h));
  render::PassTimer timer(false);
  buffer->build(gpu, u, timer);
}

namespace {

// "1/4" for 0.25, "1" for 1: the λ of a run as the table prints it.
std::string fraction(double lambda) {
  if (lambda >= 1) return std::to_string(int(std::lround(lambda)));
  return "1/" + std::to_string(int(std::lround(1 / lambda)));
}

render::SmartSettings settingsFor(bool normalized, render::DiffusionScheme scheme, int steps, double lambda, int sweeps) {
  render::SmartSettings s;
  s.normalizedLaplacian = normalized;
  s.adaptiveAlpha = true;  // α varies with the layer count: something to diffuse
  s.s = 0.7;
  s.halos = false;
  s.silhouettes = false;  // time α alone
  s.scheme = scheme;
  s.iterations = steps;
  s.lambdaAlpha = lambda;
  s.jacobiSweeps = sweeps;
  return s;
}

}  // namespace

std::vector<float> DiffusionFrame::diffuse(const render::SmartSettings& s, double* ms) {
  auto fields = render::connectFragments(*buffer, shaders, s, radius);
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  render::DiffusionSolver(shaders, s).solve(*fields);
  glFinish();
  *ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return fields->read(render::Field::Alpha);
}

std::vector<DiffusionRun> measureDiffusionSchemes(DiffusionFrame& frame, double T) {
  std::vector<DiffusionRun> runs;
  for (const bool normalized : {true, false}) {
    const std::string reading = normalized ? "normalized" : "sum";
    const double bound = normalized ? render::kExplicitStableLambdaNormalized : render::kExplicitStableLambdaSum;
    const auto with = [&](render::DiffusionScheme scheme, double lambda, int sweeps) {
      return settingsFor(normalized, scheme, static_cast<int>(std::lround(T / lambda)), lambda, sweeps);
    };
    // Reference: explicit steps 16 times finer than the reading's stability bound.
    double refMs = 0;
    const auto reference = frame.diffuse(with(render::DiffusionScheme::Explicit, bound / 16, 1), &refMs);
    const auto measure = [&](const std::string& scheme, const std::string& setting, const render::SmartSettings& s) {
      frame.diffuse(s, &refMs);  // warm-up (shader compilation)
      DiffusionRun r{reading, scheme, setting};
      const auto alpha = frame.diffuse(s, &r.ms);
      r.passes = s.iterations * render::DiffusionSolver(frame.shaders, s).dispatchesPerStep();
      double sum = 0;
      for (std::size_t i = 0; i < alpha.size(); ++i) {
        const double e = std::fabs(double(alpha[i]) - reference[i]);
        r.maxError = std::max(r.maxError, e);
        sum += e * e;
      }
      r.rmsError = alpha.empty() ? 0 : std::sqrt(sum / double(alpha.size()));
      runs.push_back(r);
    };
    for (int m : {1, 2, 4, 8})  // explicit: the bound and finer
      measure("explicit", "lambda=" + fraction(bound / m), with(render::DiffusionScheme::Explicit, bound / m, 1));
    for (double lambda : {1.0, 2.0, 4.0})  // sub-stepped: the paper's λα = 1 and beyond
      if (lambda > bound) measure("substep", "lambda=" + std::to_string(int(lambda)), with(render::DiffusionScheme::Substep, lambda, 1));
    for (double lambda : {1.0, 4.0})
      for (int sweeps : {2, 5, 10, 20})
        measure("implicit", "lambda=" + std::to_string(int(lambda)) + " sweeps=" + std::to_string(sweeps),
                with(render::DiffusionScheme::Implicit, lambda, sweeps));
  }
  return runs;
}

}  // namespace tlab::bench
