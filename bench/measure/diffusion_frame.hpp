#pragma once
// The frame `tlab bench diffusion` times the α diffusion on (Carnecky Eq. 8): one scene filled
// once into the illustration buffer with the smart style's properties; every run reconnects the
// fields, so each starts from the same α.
#include <memory>
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

}  // namespace tlab::bench
