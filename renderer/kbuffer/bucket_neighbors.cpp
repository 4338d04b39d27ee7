#include "renderer/kbuffer/bucket_neighbors.hpp"

#include <stdexcept>

#include "renderer/gpu/gl_error.hpp"

namespace tlab::render {

void findBucketNeighbors(BucketedKBuffer& buffer, gpu::ShaderCache& shaders, kbuffer::NeighborSearch search) {
  if (!buffer.settings().buckets) throw std::logic_error("the neighbour query needs a k-buffer reordered into buckets");
  auto defines = buffer.defines();
  if (search == kbuffer::NeighborSearch::BruteForce) defines.emplace_back("TLAB_BRUTE_FORCE", "1");
  const auto& program = shaders.compute("kbuffer/bucket_neighbors.comp", defines);
  buffer.ensureLinks();
  buffer.bind();
  program.use();
  glUniform1i(program.uniform("uWidth"), buffer.width());
  glUniform1i(program.uniform("uHeight"), buffer.height());
  gpu::dispatchLinear(buffer.pixels());
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  gpu::checkGl("kbuffer/bucket_neighbors.comp");
}

}  // namespace tlab::render
