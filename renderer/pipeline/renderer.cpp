#include "renderer/pipeline/renderer.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/peel/depth_peeling.hpp"
#include "renderer/styles/local_style.hpp"
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

template <typename T, typename Fits>
T* Renderer::reusableFill(Fits&& fits) const {
  T* const last = dynamic_cast<T*>(fill_.get());
  return last && fits(*last) ? last : nullptr;
}

// The fill for this frame: depth peeling when the request asks for it, else the one the style
// declares; the last frame's is kept when its size and settings still fit.
Fill* Renderer::prepareFill(const Style& style, const StyleParams& params, const RenderRequest& request,
                            const Camera& camera) {
  const int w = request.width, h = request.height;
  if (request.depthPeeling) {
    const IllustrativeSettings shading = localShadingOf(style, params);  // throws for styles that are not local
    DepthPeeling* peeling = reusableFill<DepthPeeling>([&](const DepthPeeling& p) { return p.width() == w && p.height() == h; });
    if (!peeling) fill_ = std::make_unique<DepthPeeling>(shaders_, w, h);
    peeling = static_cast<DepthPeeling*>(fill_.get());
    peeling->setShading(shading);
    return peeling;
  }
  FillSpec spec = style.fill(params);
  if (spec.kind == FillSpec::Kind::None) {
    fill_.reset();
    return nullptr;
  }
  if (spec.kind == FillSpec::Kind::BucketedKBuffer) {
    spec.kBuffer.nearPlane = camera.nearPlane;
    spec.kBuffer.farPlane = camera.farPlane;
    const auto fits = [&](const BucketedKBuffer& k) { return k.width() == w && k.height() == h && k.settings() == spec.kBuffer; };
    if (!reusableFill<BucketedKBuffer>(fits)) fill_ = std::make_unique<BucketedKBuffer>(shaders_, w, h, spec.kBuffer);
    return fill_.get();
  }
  FragmentProperties props = style.properties(params, SceneFacts{gpuScene_.componentCount()});
  if (request.allProperties) props.bits = 0x1Fu;  // every FragmentProperty
  // Keep the buffer (and its pool) across frames of the same size and layout.
  const auto fits = [&](const FragmentBuffer& b) {
    return request.initialPoolFragments == 0 && b.width() == w && b.height() == h && b.method() == request.fill &&
           b.layout().properties.bits == props.bits;
  };
  if (!reusableFill<FragmentBuffer>(fits))
    fill_ = std::make_unique<FragmentBuffer>(shaders_, w, h, FragmentLayout(props), request.fill, request.initialPoolFragments);
  auto* const buffer = static_cast<FragmentBuffer*>(fill_.get());
  buffer->setSortInCompose(spec.sortsInCompose);
  buffer->setColorPlane(spec.colorPlane);
  return buffer;
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
  timer.stopAfter(request.lastPass);
  timer.timeParts(request.timeParts);
  Fill* const fill = prepareFill(style, params, request, camera);
  FrameContext frame{scene_, gpuScene_, raster, camera, params, request.width, request.height,
                     scene_.background, fill, image, shaders_, &drawOrder_, &fields_, &sceneCache_, &timer};
  if (fill) fill->build(frame, timer);
  std::vector<std::string> operations;
  if (!fill || !fill->composesPicture())
    for (const auto& pass : style.passes(params)) {
      timer.time(pass->name(), [&] { pass->run(frame); });
      for (auto& op : pass->operations()) operations.push_back(pass->name() + ": " + op);
    }
  gpu::checkGl((request.depthPeeling ? "depth peeling style " : "rendering style ") + style.name());
  if (!request.lastPass.empty() && !timer.ran(request.lastPass)) {
    std::string names;
    for (const auto& [name, ms] : timer.passes()) names += (names.empty() ? "" : ", ") + name;
    throw std::invalid_argument(style.name() + "'s frame has no pass '" + request.lastPass + "' (its passes: " + names + ")");
  }

  if (stats) {
    *stats = RenderStats{};
    stats->triangles = gpuScene_.triangleCount();
    stats->passMilliseconds = timer.passes();
    stats->parts = timer.parts();
    stats->operations = std::move(operations);
    stats->camera = camera;
    stats->width = request.width;
    stats->height = request.height;
    describeFill(*stats);
  }
  return image;
}

void Renderer::describeFill(RenderStats& stats) const {
  if (const auto* peeling = dynamic_cast<const DepthPeeling*>(fill_.get())) stats.peelIterations = peeling->iterations();
  if (const BucketedKBuffer* kbuffer = kBuffer()) {
    stats.fragments = kbuffer->fragmentCount();
    stats.fillMethod = kbuffer->settings().buckets ? "bucketed-kbuffer" : "kbuffer";
  }
  const auto* buffer = dynamic_cast<const FragmentBuffer*>(fill_.get());
  if (!buffer) return;
  stats.fragments = buffer->fragmentCount();
  stats.rerenders = buffer->rerenders();
  stats.poolGrowths = buffer->poolGrowths();
  stats.poolCapacity = buffer->capacity();
  stats.fillMethod = fillMethodName(buffer->method());
  stats.fragmentProperties = buffer->layout().propertyNames();
  const auto counts = buffer->pixelCounts();
  std::size_t covered = 0;
  for (auto c : counts) {
    stats.maxListLength = std::max(stats.maxListLength, c);
    covered += c > 0;
  }
  stats.meanListLength = double(stats.fragments) / double(counts.size());
  stats.meanCoveredListLength = covered ? double(stats.fragments) / double(covered) : 0.0;
}

FragmentBuffer& Renderer::listsOrThrow(const std::string& what) const {
  auto* const buffer = dynamic_cast<FragmentBuffer*>(fill_.get());
  if (!buffer) throw std::logic_error(what + " a style with fragment lists (not 'opaque')");
  return *buffer;
}

std::vector<std::uint16_t> Renderer::layerCounts() const {
  const FragmentBuffer& buffer = listsOrThrow("layer counts need");
  const auto gl = buffer.pixelCounts();
  const std::size_t w = buffer.width(), h = buffer.height();
  std::vector<std::uint16_t> out(w * h);
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x)
      out[y * w + x] = static_cast<std::uint16_t>(std::min<std::uint32_t>(gl[(h - 1 - y) * w + x], 65535u));
  return out;
}

std::vector<FragmentRecord> Renderer::fragmentsAt(int x, int y) const {
  FragmentBuffer& buffer = listsOrThrow("inspecting fragments needs");  // sorts a list left to the compose pass
  if (x < 0 || y < 0 || x >= buffer.width() || y >= buffer.height())
    throw std::invalid_argument("pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the " +
                                std::to_string(buffer.width()) + "x" + std::to_string(buffer.height()) + " image");
  const std::size_t p = std::size_t(buffer.height() - 1 - y) * buffer.width() + x;
  const auto counts = buffer.pixelCounts();
  const auto heads = buffer.pixelHeads();
  const auto words = buffer.sortedRecords(heads[p], counts[p]);
  const FragmentLayout& L = buffer.layout();
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
