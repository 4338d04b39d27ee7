#pragma once
// The neighbour query of the bucketed k-buffer (seed 002, Sec. 5.1, Fig. 5).
#include "renderer/gpu/shader_cache.hpp"
#include "renderer/kbuffer/bucket_table.hpp"
#include "renderer/kbuffer/bucketed_kbuffer.hpp"

namespace tlab::render {

// For every slot, its neighbour in each of the 4 adjacent pixels (left, right, down, up): the
// fragment of the same shape with minimum ε = εn + εz, kept only when the reverse check picks
// the slot back; written to buffer.links() (byte d: the layer in the adjacent pixel, 0xFF none).
// Buckets: only the same-shape bucket of the adjacent pixel is scanned; BruteForce: every
// fragment of the adjacent pixel, filtered by shape (as the illustration buffer does).
void findBucketNeighbors(BucketedKBuffer& buffer, gpu::ShaderCache& shaders, kbuffer::NeighborSearch search);

}  // namespace tlab::render
