#pragma once
// RAII owners for GL objects. Each owns one GL name, is movable, not copyable, and deletes the
// name when it dies. They assume the GpuContext that created them is current.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>

#include "renderer/gpu/gl.hpp"

namespace tlab::gpu {

template <typename Deleter>
class GlName {
 public:
  GlName() = default;
  explicit GlName(GLuint id) : id_(id) {}
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;
  GlName(GlName&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  GlName& operator=(GlName&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  ~GlName() { reset(); }
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0) Deleter{}(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

struct BufferDeleter { void operator()(GLuint id) const { glDeleteBuffers(1, &id); } };
struct TextureDeleter { void operator()(GLuint id) const { glDeleteTextures(1, &id); } };
struct FramebufferDeleter { void operator()(GLuint id) const { glDeleteFramebuffers(1, &id); } };
struct RenderbufferDeleter { void operator()(GLuint id) const { glDeleteRenderbuffers(1, &id); } };
struct VertexArrayDeleter { void operator()(GLuint id) const { glDeleteVertexArrays(1, &id); } };
struct ProgramDeleter { void operator()(GLuint id) const { glDeleteProgram(id); } };
struct ShaderDeleter { void operator()(GLuint id) const { glDeleteShader(id); } };
struct QueryDeleter { void operator()(GLuint id) const { glDeleteQueries(1, &id); } };

using ShaderName = GlName<ShaderDeleter>;
using ProgramName = GlName<ProgramDeleter>;
using VertexArray = GlName<VertexArrayDeleter>;
using Texture = GlName<TextureDeleter>;
using Renderbuffer = GlName<RenderbufferDeleter>;
using Framebuffer = GlName<FramebufferDeleter>;
using Query = GlName<QueryDeleter>;

VertexArray makeVertexArray();
Texture makeTexture(GLenum target);
Renderbuffer makeRenderbuffer();
Framebuffer makeFramebuffer();
Query makeQuery(GLenum target);
// A buffer texture showing the first `bytes` of buffer object `buffer` as texels of `format`,
// bound to texture unit `unit` (a shader then reads it with texelFetch: one fetch for all lanes,
// where a CPU rasterizer reads a storage buffer lane by lane).
Texture bindBufferTexture(GLuint buffer, GLenum format, std::size_t bytes, GLuint unit);

// A GL buffer object with immutable-size storage that can be resized (re-created).
class Buffer {
 public:
  Buffer() = default;
  // Allocates `bytes` of storage (contents undefined unless data is given).
  explicit Buffer(std::size_t bytes, const void* data = nullptr);
  std::size_t size() const { return bytes_; }
  GLuint id() const { return name_.id(); }
  explicit operator bool() const { return static_cast<bool>(name_); }
  // Re-creates the storage with the new size when it differs (contents lost).
  void resize(std::size_t bytes);
  void upload(const void* data, std::size_t bytes, std::size_t offset = 0) const;  // const as fillWords
  void download(void* data, std::size_t bytes, std::size_t offset = 0) const;
  void clearToZero();
  // Sets the first `words` 32-bit words to `word` (a float's bits where the buffer holds floats).
  // const as bindBase is: the storage's contents are the GL's, which shaders write through const
  // handles too.
  void fillWords(std::uint32_t word, std::size_t words) const;
  // Sets the first 16 bytes to the four words `quad`, on the GL's side like fillWords (no host
  // write into a buffer that dispatches still in flight may read).
  void setFirstQuad(const std::array<std::uint32_t, 4>& quad) const;
  // Reads `bytes` at `offset` through the small buffer `staging` (at least `bytes` long): the GL
  // copies them there first and the host reads that, never a range of this (maybe large) buffer.
  void downloadThrough(const Buffer& staging, void* data, std::size_t bytes, std::size_t offset = 0) const;
  void bindBase(GLenum target, GLuint index) const;

 private:
  GlName<BufferDeleter> name_;
  std::size_t bytes_ = 0;
};

// A buffer's bytes [offset, offset + bytes) mapped into host memory for as long as it lives (RAII:
// glMapNamedBufferRange on construction, glUnmapNamedBuffer on destruction). The mapping waits for
// the GL's use of the buffer; on a CPU rasterizer it is the buffer's own memory, no copy. No bytes:
// nothing is mapped. The base of MappedRead and MappedWrite.
class Mapping {
 public:
  Mapping(const Mapping&) = delete;
  Mapping& operator=(const Mapping&) = delete;

 protected:
  Mapping(const Buffer& buffer, std::size_t bytes, std::size_t offset, GLbitfield access, const char* purpose);
  ~Mapping();
  void* data() const { return data_; }

 private:
  GLuint id_ = 0;
  void* data_ = nullptr;
};

// A read-only view of a buffer's bytes.
class MappedRead : public Mapping {
 public:
  MappedRead(const Buffer& buffer, std::size_t bytes, std::size_t offset = 0);
  template <class T>
  const T* as() const { return static_cast<const T*>(data()); }
};

// A view of a buffer's bytes for writing (and reading, where `readable`): what the host writes is
// the buffer's from the unmapping on (on a CPU rasterizer, written straight into its memory). Bytes
// of the range the host leaves unwritten keep their contents (the range is not invalidated).
class MappedWrite : public Mapping {
 public:
  MappedWrite(const Buffer& buffer, std::size_t bytes, std::size_t offset = 0, bool readable = false);
  template <class T>
  T* as() const { return static_cast<T*>(data()); }
};

// Whether a GL of this GL_RENDERER string runs on the CPU: Mesa's llvmpipe or softpipe, SwiftShader.
bool rendererRunsOnCpu(std::string_view glRenderer);
// Whether the current context's GL does (rendererRunsOnCpu of its GL_RENDERER).
bool glRunsOnCpu();
// Whether the few passes that have a host-code twin (the fill's prefix sum, the sort, the connect
// pass's phase 2, the solve's frontier steps) run it: TLAB_HOST_PASSES=on or off, or by default
// (auto) where the current context's GL runs on the CPU — there a loop over a frame's pixels, or
// over a few thousand scattered fragments, costs less than the dispatches of a shader run lane by
// lane (issue #29). The results are the same words either way (tests compare both). Throws
// GlError for another value. Read anew each time it is asked (by a fragment buffer or solver when
// made, by the connect pass each frame: a getenv and a glGetString), so tests may switch it.
bool hostPassesWanted();
// TLAB_HOST_PASSES read alone (no GL needed): the contexts check it when made, so that a wrong
// value is one line before any work. nullopt: auto.
std::optional<bool> hostPassesSetting();

// TLAB_DRAW_RUNS read alone (no GL needed; the contexts check it when made): how many runs a
// scene's triangles are drawn in (GpuScene::draw), a whole number from 1 to kMaxDrawRunsSetting,
// or nullopt for auto (the default). Throws GlError for another value.
constexpr std::size_t kMaxDrawRunsSetting = 64;
std::optional<std::size_t> drawRunsSetting();

// local_size_x of every linear compute pass (frame/compute_index.glsl).
constexpr std::size_t kComputeGroupSize = 64;

// Dispatches enough kComputeGroupSize-wide compute groups for `items` invocations as a 2-D grid that stays
// under the 65535-groups-per-dimension limit; shaders index with frame/compute_index.glsl.
void dispatchLinear(std::size_t items);

}  // namespace tlab::gpu
