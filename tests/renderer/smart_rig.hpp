#pragma once
// What the smart-transparency GL tests share: a scene's illustration buffer with its connected
// transparency fields (SmartRig), the cross-section scene of Carnecky Fig. 8, and the discrete
// energy of an α field over the links.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "renderer/ops/connect_pass.hpp"
#include "renderer/ops/diffusion_solver.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/styles/smart_style.hpp"

namespace tlab::testing {

using namespace tlab::render;

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;

// The illustration buffer of a scene plus its connected transparency fields.
struct SmartRig {
  SmartRig(Scene s, int w, int h, const std::map<std::string, std::string>& settings = {})
      : scene(std::move(s)), gpu(scene), width(w), height(h) {
    const SmartStyle style;
    params = style.resolve(settings);
    smart = SmartSettings::from(params);
    camera = scene.camera ? *scene.camera : fitCamera(scene.boundingSphere(), float(w) / float(h));
    buffer = std::make_unique<FragmentBuffer>(shaders, w, h, FragmentLayout(style.properties(params, {gpu.componentCount()})),
                                              FillMethod::CountScatter);
    RasterUniforms u;
    u.view = camera.view();
    u.projection = camera.projection(float(w) / float(h));
    PassTimer timer(false);
    buffer->build(gpu, u, timer);
    fields = connectFragments(*buffer, shaders, smart, scene.boundingSphere().radius);
    counts = buffer->pixelCounts();
    heads = buffer->pixelHeads();
  }
  // Fragment index of `layer` (0 = front) at pixel (x, y) in GL order (row 0 = bottom).
  std::uint32_t fragment(int x, int y, int layer) const {
    const std::size_t p = std::size_t(y) * width + x;
    EXPECT_LT(std::uint32_t(layer), counts[p]) << "pixel " << x << "," << y;
    return heads[p] + std::uint32_t(layer);
  }

  Scene scene;
  GpuScene gpu;
  tlab::gpu::ShaderCache shaders;
  int width, height;
  StyleParams params;
  SmartSettings smart;
  Camera camera;
  std::unique_ptr<FragmentBuffer> buffer;
  std::unique_ptr<TransparencyFields> fields;
  std::vector<std::uint32_t> counts, heads;
};

// A large back quad at z = −1 and a front quad at z = 0 covering x < 0: a cross-section like
// Carnecky Fig. 8, seen straight on; the front quad's edge lies between pixel columns 31 and 32.
inline Scene occluderScene() {
  Scene s;
  SceneObject back;
  back.name = "back";
  back.mesh = makeQuad({0, 0, -1}, {20, 0, 0}, {0, 20, 0});
  back.frontColor = {0.2f, 0.4f, 0.9f, 1};
  SceneObject front;
  front.name = "front";
  front.mesh = makeQuad({-10, 0, 0}, {10, 0, 0}, {0, 20, 0});
  front.frontColor = {0.9f, 0.5f, 0.1f, 1};
  s.objects = {back, front};
  s.camera = Camera{};
  s.camera->eye = {0, 0, 5};
  s.camera->nearPlane = 1;
  s.camera->farPlane = 10;
  return s;
}

inline double linkEnergy(const std::vector<float>& alpha, const std::vector<glm::uvec4>& links) {
  double e = 0;
  for (std::size_t i = 0; i < links.size(); ++i)
    for (int k = 0; k < 4; ++k)
      if (links[i][k] != kNone) e += std::pow(double(alpha[i]) - alpha[links[i][k]], 2);
  return e;
}

}  // namespace tlab::testing
