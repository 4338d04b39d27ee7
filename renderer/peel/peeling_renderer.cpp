#include "renderer/peel/peeling_renderer.hpp"

#include <stdexcept>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/styles/local_style.hpp"

namespace tlab::render {

PeelingRenderer::PeelingRenderer(Scene scene) : scene_(std::move(scene)), gpuScene_(scene_) {}

core::Image PeelingRenderer::render(const RenderRequest& request, PeelStats* stats) {
  if (request.width <= 0 || request.height <= 0 || request.width > 16384 || request.height > 16384)
    throw std::invalid_argument("image size must be between 1x1 and 16384x16384");
  const Style& style = findStyle(request.style);
  const StyleParams params = style.resolve(request.settings);
  const IllustrativeSettings settings = localShadingOf(style, params);
  // The same camera as Renderer::resolveCamera.
  const Camera camera = request.camera ? *request.camera
                        : scene_.camera ? *scene_.camera
                                        : fitCamera(scene_.boundingSphere(), float(request.width) / float(request.height));
  RasterUniforms raster;
  raster.view = camera.view();
  raster.projection = camera.projection(float(request.width) / float(request.height));
  raster.lighting = lightingModel(params);
  if (!peeler_ || peeler_->width() != request.width || peeler_->height() != request.height)
    peeler_ = std::make_unique<DepthPeeler>(shaders_, request.width, request.height);
  PassTimer timer(request.timePasses);
  core::Image image = peeler_->render(gpuScene_, raster, settings, scene_.background, timer);
  gpu::checkGl("depth peeling style " + style.name());
  if (stats) {
    stats->iterations = peeler_->iterations();
    stats->passMilliseconds = timer.passes();
    stats->camera = camera;
  }
  return image;
}

}  // namespace tlab::render
