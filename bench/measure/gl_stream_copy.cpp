#include "bench/measure/gl_stream_copy.hpp"

#include <algorithm>
#include <string>

#include "bench/measure/gl_timing.hpp"
#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/gl_objects.hpp"
#include "renderer/gpu/shader_program.hpp"

namespace tlab::bench {

namespace {

// After the #version line, the defines and frame/compute_index.glsl: each invocation copies
// VECS consecutive values of type WORD.
constexpr const char* kCopy = R"(
layout(std430, binding = 0) readonly buffer Src { WORD src[]; };
layout(std430, binding = 1) writeonly buffer Dst { WORD dst[]; };
uniform uint uItems;
void main() {
  uint i = linearInvocation();
  if (i >= uItems) return;
  for (uint k = 0u; k < VECS; ++k) dst[i * VECS + k] = src[i * VECS + k];
}
)";

GlCopyRate measure(std::size_t bytes, int repeats, int words) {
  const bool vec = words >= 4;
  const int vecs = vec ? words / 4 : 1;
  const std::size_t items = bytes / (4u * std::size_t(words));
  const std::string source = std::string("#version 450 core\n#define WORD ") + (vec ? "uvec4" : "uint") +
                             "\n#define VECS " + std::to_string(vecs) + "u\n" +
                             std::string(gpu::embeddedShader("frame/compute_index.glsl")) + kCopy;
  const gpu::Buffer src(bytes), dst(bytes);
  const auto program = gpu::ShaderProgram::computeFromSource(source, "the streaming copy of tlab bench floor");
  program.use();
  glUniform1ui(program.uniform("uItems"), static_cast<GLuint>(items));
  src.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  dst.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  const auto copy = [&] {
    gpu::dispatchLinear(items);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  };
  copy();  // warm-up: compilation, first touch of the pages
  GlCopyRate rate{words, 0.0};
  const double moved = 2.0 * double(items * 4u * std::size_t(words));
  for (int r = 0; r < repeats; ++r) rate.bytesPerSecond = std::max(rate.bytesPerSecond, moved / (timeGlJob(copy).wallMs / 1000.0));
  gpu::checkGl("the streaming copy of tlab bench floor");
  return rate;
}

}  // namespace

std::vector<GlCopyRate> glStreamingRates(std::size_t bytes, int repeats) {
  std::vector<GlCopyRate> rates;
  for (int words : {1, 4, 16}) rates.push_back(measure(bytes, repeats, words));
  return rates;
}

GlCopyRate fastest(const std::vector<GlCopyRate>& rates) {
  GlCopyRate best;
  for (const auto& r : rates)
    if (r.bytesPerSecond > best.bytesPerSecond) best = r;
  return best;
}

}  // namespace tlab::bench
