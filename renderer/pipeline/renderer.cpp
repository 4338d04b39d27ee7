#include "renderer/pipeline/renderer.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/styles/style.hpp"

namespace tlab::render {

Camera fitClipPlanes(Camera camera, const BoundingSphere& sphere) {
  const float distance = glm::length(camera.eye - sphere.center);
  camera.nearPlane = std::max(distance - sphere.radius * 1.05f, std::max(distance, sphere.radius) * 1e-3f);
  camera.farPlane = distance + sphere.radius * 1.05f;
  return camera;
}

Renderer::Renderer(Scene scene) : scene_(std::move(scene)), gpuScene_(scene_), drawOrder_(scene_) {}

Camera Renderer::resolveCamera(const RenderRequest& request) const {
  if (request.camera) return *request.camera;
  if (scene_.camera) return *scene_.camera;
  return fitCamera(scene_.boundingSphere(), float(request.width) / float(request.height));
}

core::Image Renderer::render(const RenderRequest& request, RenderStats* stats) {
  if (request.width <= 0 || request.height <= 0 || request.width > 16384 || request.height > 16384)
    throw std::invalid_argument("image size must be between 1x1 and 16384x16384");
  const Style& style = findStyle(request.style);
  const StyleParams params = style.resolve(request.settings);
  const Camera camera = resolveCamera(request);
  RasterUniforms raster;
  raster.view = camera.view();
  raster.projection = camera.projection(float(request.width) / float(request.height));
  raster.lighting = lightingModel(params);

  core::Image image(request.width, request.height, scene_.background);
  PassTimer timer(request.timePasses);
  std::optional<KBufferSettings> kBufferSettings = style.kBufferFill(params);
  if (kBufferSettings) {
    kBufferSettings->nearPlane = camera.nearPlane;
    kBufferSettings->farPlane = camera.farPlane;
    buffer_.reset();
    const bool reusable = kbuffer_ && kbuffer_->width() == request.width && kbuffer_->height() == request.height &&
                          kbuffer_->settings() == *kBufferSettings;
    if (!reusable) kbuffer_ = std::make_unique<BucketedKBuffer>(shaders_, request.width, request.height, *kBufferSettings);
    kbuffer_->build(gpuScene_, raster, timer);
  } else if (style.usesFragmentLists()) {
    kbuffer_.reset();
    FragmentProperties props = style.properties(params, SceneFacts{gpuScene_.componentCount()});
    if (request.allProperties) props.bits = 0x1Fu;  // every FragmentProperty
    const FragmentLayout layout(props);
    // Keep the buffer (and its pool) across frames of the same size and layout.
    const bool reusable = buffer_ && request.initialPoolFragments == 0 && buffer_->width() == request.width &&
                          buffer_->height() == request.height && buffer_->method() == request.fill &&
                          buffer_->layout().properties.bits == props.bits;
    if (!reusable)
      buffer_ = std::make_unique<FragmentBuffer>(shaders_, request.width, request.height, layout, request.fill,
                                                 request.initialPoolFragments);
    buffer_->build(gpuScene_, raster, timer);
  } else {
    buffer_.reset();
    kbuffer_.reset();
  }
  FrameContext frame{scene_, gpuScene_, raster, camera, params, request.width, request.height,
                     scene_.background, buffer_.get(), image, shaders_, &drawOrder_, kbuffer_.get()};
  std::vector<std::string> operations;
  for (const auto& pass : style.passes(params)) {
    timer.time(pass->name(), [&] { pass->run(frame); });
    for (auto& op : pass->operations()) operations.push_back(pass->name() + ": " + op);
  }
  gpu::checkGl("rendering style " + style.name());

  if (stats) {
    *stats = RenderStats{};
    stats->triangles = gpuScene_.triangleCount();
    stats->passMilliseconds = timer.passes();
    stats->operations = std::move(operations);
    stats->camera = camera;
    stats->width = request.width;
    stats->height = request.height;
    if (kbuffer_) {
      stats->fragments = kbuffer_->fragmentCount();
      stats->fillMethod = kbuffer_->settings().buckets ? "bucketed-kbuffer" : "kbuffer";
    }
    if (buffer_) {
      stats->fragments = buffer_->fragmentCount();
      stats->rerenders = buffer_->rerenders();
      stats->poolGrowths = buffer_->poolGrowths();
      stats->poolCapacity = buffer_->capacity();
      stats->fillMethod = fillMethodName(buffer_->method());
      stats->fragmentProperties = buffer_->layout().propertyNames();
      const auto counts = buffer_->pixelCounts();
      std::size_t covered = 0;
      for (auto c : counts) {
        stats->maxListLength = std::max(stats->maxListLength, c);
        covered += c > 0;
      }
      stats->meanListLength = double(stats->fragments) / double(counts.size());
      stats->meanCoveredListLength = covered ? double(stats->fragments) / double(covered) : 0.0;
    }
  }
  return image;
}

std::vector<std::uint16_t> Renderer::layerCounts() const {
  if (!buffer_) throw std::logic_error("layer counts need a style with fragment lists (not 'opaque')");
  const auto gl = buffer_->pixelCounts();
  const std::size_t w = buffer_->width(), h = buffer_->height();
  std::vector<std::uint16_t> out(w * h);
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x)
      out[y * w + x] = static_cast<std::uint16_t>(std::min<std::uint32_t>(gl[(h - 1 - y) * w + x], 65535u));
  return out;
}

std::vector<FragmentRecord> Renderer::fragmentsAt(int x, int y) const {
  if (!buffer_) throw std::logic_error("inspecting fragments needs a style with fragment lists (not 'opaque')");
  if (x < 0 || y < 0 || x >= buffer_->width() || y >= buffer_->height())
    throw std::invalid_argument("pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the " +
                                std::to_string(buffer_->width()) + "x" + std::to_string(buffer_->height()) + " image");
  const std::size_t p = std::size_t(buffer_->height() - 1 - y) * buffer_->width() + x;
  const auto counts = buffer_->pixelCounts();
  const auto heads = buffer_->pixelHeads();
  const auto words = buffer_->sortedRecords(heads[p], counts[p]);
  const FragmentLayout& L = buffer_->layout();
  const auto f = [&](std::size_t i, std::uint32_t off) {
    float v;
    std::memcpy(&v, &words[i * L.stride + off], 4);
    return v;
  };
  std::vector<FragmentRecord> out;
  for (std::size_t i = 0; i < counts[p]; ++i) {
    FragmentRecord r;
    r.depth = f(i, 0);
    r.triangle = words[i * L.stride + 1];
    if (L.properties.has(FragmentProperty::Color)) {
      const std::uint32_t c = words[i * L.stride + L.colorOffset];
      r.color = glm::vec4(c & 0xFF, (c >> 8) & 0xFF, (c >> 16) & 0xFF, c >> 24) / 255.0f;
    }
    if (L.properties.has(FragmentProperty::Normal))
      r.normal = decodeNormal(words[i * L.stride + L.normalOffset]);
    if (L.properties.has(FragmentProperty::DepthGradient))
      r.depthGradient = {f(i, L.depthGradientOffset), f(i, L.depthGradientOffset + 1)};
    if (L.properties.has(FragmentProperty::Ids)) {
      const std::uint32_t ids = words[i * L.stride + L.idsOffset];
      r.object = ids & 0xFFFF;
      r.component = (ids >> 16) & 0x7FFF;
      r.frontFacing = (ids >> 31) != 0;
    }
    if (L.properties.has(FragmentProperty::SurfaceParams)) r.st = {f(i, L.stOffset), f(i, L.stOffset + 1)};
    out.push_back(r);
  }
  return out;
}

}  // namespace tlab::render
