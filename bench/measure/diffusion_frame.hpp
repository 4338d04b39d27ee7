#pragma once
// What `tlab bench diffusion` measures (Carnecky Eq. 8): the frame the α diffusion is timed on —
// one scene filled once into the illustration buffer with the smart style's properties, every run
// reconnecting the fields so each starts from the same α — and the error of each diffusion scheme
// (explicit at its stability bound, sub-stepped, implicit with Jacobi sweeps) against run time,
// for both readings of Eq. 8's Laplacian.
#include <memory>
#include <string>
#include <vector>

#include "renderer/buffer/fragment_buffer.hpp"
#include "renderer/frame/gpu_scene.hpp"
#include "renderer/gpu/shader_cache.hpp"
#include "renderer/ops/smart_settings.hpp"
#include "renderer/scene/scene.hpp"

namespace tlab::bench {

struct DiffusionFrame {
  render::Scene scene;
  render::GpuScene gpu;
  gpu::ShaderCache shaders;
  std::unique_ptr<render::FragmentBuffer> buffer;
  float radius;

  DiffusionFrame(render::Scene s, int w, int h);
  // α after diffusing for the settings' n·λα, and the milliseconds the solve took.
  std::vector<float> diffuse(const render::SmartSettings& s, double* ms);
};

struct DiffusionRun {
  std::string laplacian;  // normalized | sum
  std::string scheme;     // explicit | substep | implicit
  std::string setting;    // "lambda=1/4", "lambda=4 sweeps=10"
  int passes = 0;
  double ms = 0, maxError = 0, rmsError = 0;
};

// Every scheme diffusing to time `T` = n·λα, against explicit steps 16 times finer than the
// reading's stability bound.
std::vector<DiffusionRun> measureDiffusionSchemes(DiffusionFrame& frame, double T);

}  // namespace tlab::bench
