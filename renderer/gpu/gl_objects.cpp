#include "renderer/gpu/gl_objects.hpp"

#include <charconv>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "renderer/gpu/gl_error.hpp"

namespace tlab::gpu {

VertexArray makeVertexArray() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return VertexArray(id);
}
Texture makeTexture(GLenum target) {
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  return Texture(id);
}
Texture bindBufferTexture(GLuint buffer, GLenum format, std::size_t bytes, GLuint unit) {
  Texture t = makeTexture(GL_TEXTURE_BUFFER);
  glTextureBufferRange(t.id(), format, buffer, 0, GLsizeiptr(bytes));
  glBindTextureUnit(unit, t.id());
  return t;
}
Renderbuffer makeRenderbuffer() {
  GLuint id = 0;
  glCreateRenderbuffers(1, &id);
  return Renderbuffer(id);
}
Framebuffer makeFramebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  return Framebuffer(id);
}
Query makeQuery(GLenum target) {
  GLuint id = 0;
  glCreateQueries(target, 1, &id);
  return Query(id);
}

Buffer::Buffer(std::size_t bytes, const void* data) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  name_ = GlName<BufferDeleter>(id);
  bytes_ = bytes;
  // GL rejects zero-sized storage; keep one word so binding stays valid.
  glNamedBufferStorage(id, static_cast<GLsizeiptr>(bytes == 0 ? 4 : bytes), data,
                       GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT | GL_MAP_WRITE_BIT);
  checkGl("allocating a buffer of " + std::to_string(bytes) + " bytes");
}

void Buffer::resize(std::size_t bytes) {
  if (name_ && bytes == bytes_) return;
  *this = Buffer(bytes);
}

void Buffer::upload(const void* data, std::size_t bytes, std::size_t offset) const {
  if (bytes == 0) return;
  glNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::download(void* data, std::size_t bytes, std::size_t offset) const {
  if (bytes == 0) return;
  glGetNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::clearToZero() {
  glClearNamedBufferData(id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
}

void Buffer::fillWords(std::uint32_t word, std::size_t words) const {
  if (words == 0) return;
  glClearNamedBufferSubData(id(), GL_R32UI, 0, static_cast<GLsizeiptr>(words * 4), GL_RED_INTEGER, GL_UNSIGNED_INT, &word);
}

void Buffer::setFirstQuad(const std::array<std::uint32_t, 4>& quad) const {
  glClearNamedBufferSubData(id(), GL_RGBA32UI, 0, 16, GL_RGBA_INTEGER, GL_UNSIGNED_INT, quad.data());
}

void Buffer::downloadThrough(const Buffer& staging, void* data, std::size_t bytes, std::size_t offset) const {
  if (bytes == 0) return;
  if (bytes > staging.size()) throw std::logic_error("a staging buffer smaller than the bytes read through it");
  glCopyNamedBufferSubData(id(), staging.id(), static_cast<GLintptr>(offset), 0, static_cast<GLsizeiptr>(bytes));
  staging.download(data, bytes);
}

Mapping::Mapping(const Buffer& buffer, std::size_t bytes, std::size_t offset, GLbitfield access, const char* purpose)
    : id_(buffer.id()) {
  if (bytes == 0) return;
  data_ = glMapNamedBufferRange(id_, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), access);
  if (!data_) throw GlError("mapping " + std::to_string(bytes) + " bytes of a buffer for " + purpose + " failed");
}

Mapping::~Mapping() {
  if (data_) glUnmapNamedBuffer(id_);
}

MappedRead::MappedRead(const Buffer& buffer, std::size_t bytes, std::size_t offset)
    : Mapping(buffer, bytes, offset, GL_MAP_READ_BIT, "reading") {}

MappedWrite::MappedWrite(const Buffer& buffer, std::size_t bytes, std::size_t offset, bool readable)
    : Mapping(buffer, bytes, offset, GL_MAP_WRITE_BIT | (readable ? GL_MAP_READ_BIT : 0), "writing") {}

bool rendererRunsOnCpu(std::string_view name) {
  return name.starts_with("llvmpipe") || name.starts_with("softpipe") || name.find("SwiftShader") != std::string_view::npos;
}

std::optional<bool> hostPassesSetting() {
  const char* set = std::getenv("TLAB_HOST_PASSES");
  const std::string value = set ? set : "auto";
  if (value == "on") return true;
  if (value == "off") return false;
  if (value != "auto") throw GlError("TLAB_HOST_PASSES must be auto, on or off, not '" + value + "'");
  return std::nullopt;
}

std::optional<std::size_t> drawRunsSetting() {
  const char* set = std::getenv("TLAB_DRAW_RUNS");
  const std::string value = set ? set : "auto";
  if (value == "auto") return std::nullopt;
  std::size_t runs = 0;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), runs);
  if (error != std::errc() || end != value.data() + value.size() || runs < 1 || runs > kMaxDrawRunsSetting)
    throw GlError("TLAB_DRAW_RUNS must be auto or a whole number from 1 to " + std::to_string(kMaxDrawRunsSetting) +
                  ", not '" + value + "'");
  return runs;
}

bool glRunsOnCpu() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer && rendererRunsOnCpu(renderer);
}

bool hostPassesWanted() {
  if (const std::optional<bool> set = hostPassesSetting()) return *set;
  return glRunsOnCpu();
}

void Buffer::bindBase(GLenum target, GLuint index) const { glBindBufferBase(target, index, id()); }

void dispatchLinear(std::size_t items) {
  const std::size_t groups = (items + kComputeGroupSize - 1) / kComputeGroupSize;
  const std::size_t perRow = 32768;
  const auto x = static_cast<GLuint>(groups < perRow ? groups : perRow);
  const auto y = static_cast<GLuint>((groups + perRow - 1) / perRow);
  if (x > 0) glDispatchCompute(x, y, 1);
}

}  // namespace tlab::gpu
