#pragma once
// The picture flow: Scene → (fill → sort → the style's operators → compose) → Image. The fill is
// the one the style declares (pipeline/fill.hpp), or depth peeling when the request asks for it.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/buffer/fragment_buffer.hpp"
#include "renderer/frame/pass_timer.hpp"
#include "core/image.hpp"
#include "renderer/ops/group_draw_order.hpp"
#include "renderer/ops/transparency_fields.hpp"
#include "renderer/kbuffer/bucketed_kbuffer.hpp"
#include "renderer/frame/gpu_scene.hpp"
#include "renderer/frame/scene_cache.hpp"
#include "renderer/scene/scene.hpp"
#include "renderer/params/style_params.hpp"

namespace tlab::render {

class Style;

struct RenderRequest {
  int width = 512;
  int height = 512;
  std::string style = "constant";
  std::map<std::string, std::string> settings;  // --set key=value
  std::optional<Camera> camera;                  // default: the scene's own, else fitted
  FillMethod fill = FillMethod::CountScatter;
  std::size_t initialPoolFragments = 0;          // 0: one per pixel
  bool allProperties = false;                    // store every fragment property (for inspect)
  // Depth peeling (IRIS Sec. 5.1) instead of the style's fill: local styles only (constant, angle,
  // normal-variation, iris); fill, initialPoolFragments and allProperties do not apply.
  bool depthPeeling = false;
  bool timePasses = true;
  // Benchmarks only: also time the passes' parts (PassTimer::part; RenderStats::parts), each between
  // two glFinish calls.
  bool timeParts = false;
  // Benchmarks only: the frame ends after this pass ("fill", "sort" or one of the style's passes;
  // PassTimer::stopAfter), leaving the picture unfinished. Empty: every pass.
  std::string lastPass;
};

struct RenderStats {
  std::uint64_t fragments = 0;
  std::uint32_t maxListLength = 0;
  double meanListLength = 0.0;         // over all pixels
  double meanCoveredListLength = 0.0;  // over pixels with at least one fragment
  int rerenders = 0;
  int poolGrowths = 0;
  std::size_t poolCapacity = 0;
  std::size_t triangles = 0;
  std::string fillMethod;              // empty for depth peeling and for styles without a fill
  int peelIterations = 0;              // depth peeling: layers + 1
  std::vector<std::string> fragmentProperties;
  std::vector<std::pair<std::string, double>> passMilliseconds;  // in the order they ran
  std::vector<PassTimer::Part> parts;  // with RenderRequest::timeParts, in the order they first ran
  std::vector<std::string> operations;  // "pass: what it did or left out", where a pass says
  Camera camera;
  int width = 0, height = 0;
};

// A fragment as `tlab inspect` shows it (all properties of the sorted list at one pixel).
struct FragmentRecord {
  float depth = 0;
  std::uint32_t triangle = 0;
  glm::vec4 color{0};
  glm::vec3 normal{0};
  glm::vec2 depthGradient{0};
  std::uint32_t object = 0, component = 0;
  bool frontFacing = false;
  glm::vec2 st{0};
};

class Renderer {
 public:
  // Uploads the scene; a GpuContext must be current.
  explicit Renderer(Scene scene);
  const Scene& scene() const { return scene_; }

  // The camera a request resolves to (given, the scene's own, or fitted to the bounding sphere).
  Camera resolveCamera(const RenderRequest& request) const;

  core::Image render(const RenderRequest& request, RenderStats* stats = nullptr);

  // After render(): per-pixel fragment counts (row 0 = top) and one pixel's sorted list (x, y with
  // row 0 = top). Both need a style with fragment lists.
  std::vector<std::uint16_t> layerCounts() const;
  std::vector<FragmentRecord> fragmentsAt(int x, int y) const;
  // After render() with a style that fills with the bucketed k-buffer: that buffer, else null.
  const BucketedKBuffer* kBuffer() const { return dynamic_cast<const BucketedKBuffer*>(fill_.get()); }
  // After render() with smart transparency: its fields (links, flags, α, β, γ) as the frame left them.
  const TransparencyFields& transparencyFields() const { return fields_; }

 private:
  Fill* prepareFill(const Style& style, const StyleParams& params, const RenderRequest& request, const Camera& camera);
  // The fill of the last frame as T when it is one, and when `fits` says it suits this frame.
  template <typename T, typename Fits>
  T* reusableFill(Fits&& fits) const;
  FragmentBuffer& listsOrThrow(const std::string& what) const;
  void describeFill(RenderStats& stats) const;

  Scene scene_;
  GpuScene gpuScene_;
  gpu::ShaderCache shaders_;
  std::unique_ptr<Fill> fill_;  // kept across frames of the same size and settings (its pool, its GL objects)
  GroupDrawOrder drawOrder_;    // state across successive frames (seed 004, Alg. 1 line 1)
  TransparencyFields fields_;   // smart transparency's fields: memory kept across frames (issue #29)
  SceneCache sceneCache_;       // what styles derive from the scene alone (view-dependent's edges)
};

// Sets near/far so the scene's bounding sphere lies between them.
Camera fitClipPlanes(Camera camera, const BoundingSphere& sphere);

}  // namespace tlab::render
