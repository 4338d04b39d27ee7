#include "bench/measure/diffusion_frame.hpp"

#include <chrono>

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

std::vector<float> DiffusionFrame::diffuse(const render::SmartSettings& s, double* ms) {
  auto fields = render::connectFragments(*buffer, shaders, s, radius);
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  render::DiffusionSolver(shaders, s).solve(*fields);
  glFinish();
  *ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return fields->read(render::Field::Alpha);
}

}  // namespace tlab::bench
