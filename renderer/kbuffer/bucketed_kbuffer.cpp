#include "renderer/kbuffer/bucketed_kbuffer.hpp"

#include <sstream>
#include <stdexcept>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/frame/frame_context.hpp"
#include "renderer/kbuffer/bucket_table.hpp"

namespace tlab::render {

namespace {
// Binding points of kbuffer/kbuffer_layout.glsl.
enum Binding : GLuint { kZ = 0, kTable = 1, kData = 2, kLinks = 3, kCurvature = 4 };
}  // namespace

BucketedKBuffer::BucketedKBuffer(gpu::ShaderCache& shaders, int width, int height, KBufferSettings settings)
    : shaders_(shaders), width_(width), height_(height), settings_(settings) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("image size must be positive");
  if (settings_.k < 1 || settings_.k > kbuffer::kMaxLayers)
    throw std::invalid_argument("k-buffer depth k = " + std::to_string(settings_.k) + " is outside 1..32");
  GLint64 limit = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
  const std::size_t slots = pixels() * settings_.k;
  // The largest array is D (8 bytes per slot).
  if (double(slots) * 8.0 > double(limit)) {
    std::ostringstream msg;
    msg << "the bucketed k-buffer needs " << width << "x" << height << "x" << settings_.k
        << " slots x 8 bytes of colour and normal, more than the " << limit / (1024 * 1024)
        << " MiB shader storage limit: use a lower resolution or a smaller k";
    throw gpu::GlError(msg.str());
  }
  z_ = gpu::Buffer(slots * 4);
  table_ = gpu::Buffer(settings_.buckets ? slots * 4 : 4);
  data_ = gpu::Buffer(slots * 8);
  emptyFbo_ = gpu::makeFramebuffer();
  glNamedFramebufferParameteri(emptyFbo_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, width);
  glNamedFramebufferParameteri(emptyFbo_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, height);
  const auto d = defines();
  insertProgram_ = &shaders.graphics("buffer/scene_geometry.vert", "kbuffer/kbuffer_insert.frag", d);
  if (settings_.buckets) bucketProgram_ = &shaders.compute("kbuffer/bucket_table.comp", d);
}

gpu::ShaderDefines BucketedKBuffer::defines() const {
  gpu::ShaderDefines d{{"TLAB_K", std::to_string(settings_.k) + "u"}};
  if (settings_.buckets) d.emplace_back("TLAB_BUCKETS", "1");
  return d;
}

const gpu::ShaderProgram& BucketedKBuffer::dataProgram(const RasterUniforms& u) const {
  return shaders_.graphics("buffer/scene_geometry.vert", "kbuffer/kbuffer_data.frag", withLighting(defines(), u.lighting));
}

void BucketedKBuffer::rasterize(const gpu::ShaderProgram& program, const GpuScene& scene, const RasterUniforms& u) const {
  beginFragmentCapture(emptyFbo_, width_, height_, program, u);
  glUniform1i(program.uniform("uShapeFromComponent"), settings_.shapeId == ShapeIdSource::Component ? 1 : 0);
  glUniform1f(program.uniform("uNear"), settings_.nearPlane);
  glUniform1f(program.uniform("uFar"), settings_.farPlane);
  endFragmentCapture(scene, program);
}

void BucketedKBuffer::build(FrameContext& frame, PassTimer& timer) { build(frame.gpuScene, frame.raster, timer); }

void BucketedKBuffer::build(const GpuScene& scene, const RasterUniforms& uniforms, PassTimer& timer) {
  bind();
  timer.time("z-insert", [&] {
    const GLuint empty = kbuffer::kEmpty;
    glClearNamedBufferData(z_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &empty);
    rasterize(*insertProgram_, scene, uniforms);
  });
  if (settings_.buckets)
    timer.time("buckets", [&] {
      bucketProgram_->use();
      glUniform1ui(bucketProgram_->uniform("uPixels"), static_cast<GLuint>(pixels()));
      gpu::dispatchLinear(pixels());
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    });
  timer.time("data", [&] {
    data_.clearToZero();
    rasterize(dataProgram(uniforms), scene, uniforms);
  });
  gpu::checkGl("building the bucketed k-buffer");
}

void BucketedKBuffer::bind() const {
  z_.bindBase(GL_SHADER_STORAGE_BUFFER, kZ);
  table_.bindBase(GL_SHADER_STORAGE_BUFFER, kTable);
  data_.bindBase(GL_SHADER_STORAGE_BUFFER, kData);
  if (links_) links_.bindBase(GL_SHADER_STORAGE_BUFFER, kLinks);
  if (curvature_) curvature_.bindBase(GL_SHADER_STORAGE_BUFFER, kCurvature);
}

void BucketedKBuffer::ensureLinks() {
  const std::size_t slots = pixels() * settings_.k;
  if (!links_) links_ = gpu::Buffer(slots * 4);
  if (!curvature_) curvature_ = gpu::Buffer(slots * 4);
}

std::size_t BucketedKBuffer::bytesPerSlot() const { return settings_.buckets ? 16 : 12; }

namespace {
template <typename T>
std::vector<T> download(const gpu::Buffer& b, std::size_t count) {
  if (!b) throw std::logic_error("this bucketed k-buffer read-back was not computed");
  std::vector<T> v(count);
  b.download(v.data(), count * sizeof(T));
  return v;
}
}  // namespace

std::vector<std::uint32_t> BucketedKBuffer::zRecords() const { return download<std::uint32_t>(z_, pixels() * k()); }
std::vector<std::uint32_t> BucketedKBuffer::bucketTable() const {
  if (!settings_.buckets) throw std::logic_error("a k-buffer without buckets has no bucket table");
  return download<std::uint32_t>(table_, pixels() * k());
}
std::vector<std::uint32_t> BucketedKBuffer::dataRecords() const { return download<std::uint32_t>(data_, pixels() * k() * 2); }
std::vector<std::uint32_t> BucketedKBuffer::neighborLinks() const { return download<std::uint32_t>(links_, pixels() * k()); }
std::vector<float> BucketedKBuffer::curvatureValues() const { return download<float>(curvature_, pixels() * k()); }

std::uint64_t BucketedKBuffer::fragmentCount() const {
  std::uint64_t n = 0;
  for (auto key : zRecords()) n += key != kbuffer::kEmpty;
  return n;
}

}  // namespace tlab::render
