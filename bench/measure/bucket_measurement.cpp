#include "bench/measure/bucket_measurement.hpp"

#include "bench/measure/frame_timing.hpp"
#include "bench/measure/gl_timing.hpp"
#include "renderer/kbuffer/bucket_neighbors.hpp"
#include "renderer/ops/screen_space_curvature.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"

namespace tlab::bench {

BucketRow measureBuckets(const BucketBench& o, int objects) {
  const int width = o.width, height = o.height;
  const render::Scene scene =
      render::loadScene("builtin:quad-stack?n=" + std::to_string(o.layers) + "&m=" + std::to_string(objects));
  const render::Camera camera = *scene.camera;
  render::GpuScene gpuScene(scene);
  gpu::ShaderCache shaders;
  render::RasterUniforms raster;
  raster.view = camera.view();
  raster.projection = camera.projection(float(width) / float(height));
  render::KBufferSettings settings;
  settings.k = static_cast<std::uint32_t>(o.k);
  settings.nearPlane = camera.nearPlane;
  settings.farPlane = camera.farPlane;
  render::BucketedKBuffer kb(shaders, width, height, settings);
  render::PassTimer warmTimer(true);
  kb.build(gpuScene, raster, warmTimer);  // compiles the fill shaders
  render::PassTimer timer(true);
  kb.build(gpuScene, raster, timer);
  BucketRow row;
  row.objects = objects;
  row.fragments = kb.fragmentCount();
  row.zInsertMs = timer.get("z-insert");
  row.bucketsMs = timer.get("buckets");
  row.dataMs = timer.get("data");
  using render::kbuffer::NeighborSearch;
  render::findBucketNeighbors(kb, shaders, NeighborSearch::Buckets);
  render::findBucketNeighbors(kb, shaders, NeighborSearch::BruteForce);
  std::vector<double> bw, bc, fw, fc;
  for (int i = 0; i < o.repeats; ++i) {
    const GlTiming b = timeGlJob([&] { render::findBucketNeighbors(kb, shaders, NeighborSearch::Buckets); });
    const GlTiming f = timeGlJob([&] { render::findBucketNeighbors(kb, shaders, NeighborSearch::BruteForce); });
    bw.push_back(b.wallMs), bc.push_back(b.cpuMs), fw.push_back(f.wallMs), fc.push_back(f.cpuMs);
  }
  row.bucketQuery = {median(bw), median(bc)};
  row.bruteQuery = {median(fw), median(fc)};
  render::computeScreenSpaceCurvature(kb, shaders, 64.0f);
  row.curvatureMs = timeGlJob([&] { render::computeScreenSpaceCurvature(kb, shaders, 64.0f); }).wallMs;
  // The floor: a whole plain k-buffer frame (Z pass, data pass, blending with constant α).
  render::Renderer renderer(scene);
  render::RenderRequest plain;
  plain.width = width;
  plain.height = height;
  plain.style = "curvature";
  plain.settings = {{"k", std::to_string(o.k)}, {"mode", "plain"}};
  plain.timePasses = false;
  renderer.render(plain);
  std::vector<double> pw, pc;
  for (int i = 0; i < o.repeats; ++i) {
    const GlTiming t = timeGlJob([&] { renderer.render(plain); });
    pw.push_back(t.wallMs), pc.push_back(t.cpuMs);
  }
  row.plainFrame = {median(pw), median(pc)};
  return row;
}

}  // namespace tlab::bench
