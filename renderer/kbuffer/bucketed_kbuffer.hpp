#pragma once
// The bucketed k-buffer (seed 002, Murray et al., Sec. 4): another way to fill, a sibling of the
// illustration buffer (FragmentBuffer) and of depth peeling. Per pixel, k slots in each of
//  Z  the k nearest fragments, depth | shape id, inserted in depth order with atomicMin
//     (pass "z-insert", kbuffer/kbuffer_insert.frag);
//  B  the bucket hash table after Z is reordered by shape id (pass "buckets",
//     kbuffer/bucket_table.comp);
//  D  colour and packed normal of each kept fragment, found by bucket lookup and binary search
//     in a second geometry pass (pass "data", kbuffer/kbuffer_data.frag).
// Without buckets (`Settings::buckets = false`) it is a plain dual-pass k-buffer: Z stays in depth
// order and the data pass searches the whole list. The neighbour links and the curvature κ of
// each slot live here too, written by findNeighbors() and ops/screen_space_curvature.
// The CPU model of Z and B is kbuffer/bucket_table.hpp.
#include <cstdint>
#include <vector>

#include "renderer/frame/fragment_capture.hpp"
#include "renderer/gpu/gl_objects.hpp"
#include "renderer/gpu/shader_cache.hpp"
#include "renderer/frame/fill.hpp"
#include "renderer/frame/gpu_scene.hpp"
#include "renderer/frame/pass_timer.hpp"

namespace tlab::render {

enum class ShapeIdSource { Object, Component };

struct KBufferSettings {
  std::uint32_t k = 16;          // layers kept per pixel (1..32)
  bool buckets = true;           // reorder Z by shape id and build B (false: plain k-buffer)
  ShapeIdSource shapeId = ShapeIdSource::Object;
  float nearPlane = 0.1f, farPlane = 100.0f;  // eye depth mapped to [0, 1] over [near, far]
  bool operator==(const KBufferSettings&) const = default;
};

class BucketedKBuffer final : public Fill {
 public:
  // Throws std::invalid_argument for k outside 1..32 and gpu::GlError when W·H·k·8 bytes exceed
  // the shader storage block limit.
  BucketedKBuffer(gpu::ShaderCache& shaders, int width, int height, KBufferSettings settings);

  // Z pass, bucket pass (with buckets), data pass; timed as "z-insert", "buckets", "data".
  void build(const GpuScene& scene, const RasterUniforms& uniforms, PassTimer& timer);
  void build(FrameContext& frame, PassTimer& timer) override;  // Fill: the frame's scene and camera

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t pixels() const { return std::size_t(width_) * height_; }
  std::uint32_t k() const { return settings_.k; }
  const KBufferSettings& settings() const { return settings_; }
  gpu::ShaderDefines defines() const;  // TLAB_K, TLAB_BUCKETS for the passes that read the buffer

  // Binds Z, B, D, links and κ at their points of kbuffer/kbuffer_layout.glsl.
  void bind() const;
  // Allocates the neighbour links (1 word per slot) and κ (1 float per slot) on first use.
  void ensureLinks();
  const gpu::Buffer& links() const { return links_; }
  const gpu::Buffer& curvature() const { return curvature_; }

  // Bytes per fragment slot of the structures a frame needs (Z + D, + B with buckets), and of
  // the neighbour links and κ added by the curvature style.
  std::size_t bytesPerSlot() const;
  static constexpr std::size_t kLinkBytesPerSlot = 4 + 4;  // links + κ

  // Read-backs, GL pixel order (row 0 = bottom), k words (Z, B, links: byte d = neighbour layer in direction d, 0xFF none), 2k words (D).
  std::vector<std::uint32_t> zRecords() const;
  std::vector<std::uint32_t> bucketTable() const;
  std::vector<std::uint32_t> dataRecords() const;
  std::vector<std::uint32_t> neighborLinks() const;
  std::vector<float> curvatureValues() const;
  std::uint64_t fragmentCount() const;  // occupied Z slots

 private:
  void rasterize(const gpu::ShaderProgram& program, const GpuScene& scene, const RasterUniforms& u) const;
  // The data pass (kbuffer/kbuffer_data.frag shades) for u's lighting model (withLighting).
  const gpu::ShaderProgram& dataProgram(const RasterUniforms& u) const;

  gpu::ShaderCache& shaders_;
  int width_, height_;
  KBufferSettings settings_;
  gpu::Framebuffer emptyFbo_;
  gpu::Buffer z_, table_, data_, links_, curvature_;
  const gpu::ShaderProgram* insertProgram_ = nullptr;
  const gpu::ShaderProgram* bucketProgram_ = nullptr;
};

}  // namespace tlab::render
