#pragma once
// The per-pixel structures of the bucketed k-buffer (seed 002, Murray et al., Sec. 4), on the CPU:
// the exact reference the GPU passes (kbuffer/*.frag, *.comp) are tested against, and the place
// where the packing of Z and B is written down once.
//
//  Z: the n <= k nearest fragments of a pixel. After the Z pass a record is depth (16 bits, MSB)
//     | shape id (16 bits), ascending; after the reorder it is shape id (MSB) | depth, ascending,
//     so fragments of one shape are consecutive and sorted by depth inside their run (Sec. 4.2).
//  B: a hash table of k slots per pixel, one bucket per shape: shape id (16 bits) | first (8 bits)
//     | last (8 bits) fragment index, stored at H(b) = b mod k with linear probing (Sec. 4.1).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace tlab::render::kbuffer {

constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;  // an unused slot of Z or of B
constexpr std::uint32_t kMaxLayers = 32;       // k: the shaders keep one pixel's list in registers
constexpr std::uint32_t kMaxShapeId = 0xFFFEu; // 0xFFFF is reserved: (depth 1, shape 0xFFFF) == kEmpty

// seed 002, Sec. 4.2: depth as MSB so an integer comparison orders by depth first.
std::uint32_t packDepthFirst(std::uint16_t depth, std::uint16_t shape);
// After the reorder: shape id as MSB (Sec. 4.2, "depth and shape number are swapped").
std::uint32_t packShapeFirst(std::uint16_t depth, std::uint16_t shape);
std::uint32_t swapHalves(std::uint32_t key);
std::uint16_t shapeOfShapeFirst(std::uint32_t key);
std::uint16_t depthOfShapeFirst(std::uint32_t key);
// Eye depth mapped linearly from [near, far] to [0, 65535].
std::uint16_t quantizeDepth(float depth01);
float depthOf16(std::uint16_t depth);

struct Bucket {
  std::uint16_t shape = 0;
  std::uint32_t first = 0, last = 0;  // inclusive range of Z indices
  bool operator==(const Bucket&) const = default;
};
std::uint32_t packBucket(const Bucket& b);
Bucket unpackBucket(std::uint32_t word);

// Sec. 4.2, Z pass: inserts `key` into the ascending list `z` (k slots, kEmpty = free) the way
// the atomicMin chain of kbuffer/kbuffer_insert.frag does; a key beyond the k nearest is dropped.
void insertNearest(std::span<std::uint32_t> z, std::uint32_t key);

// Sec. 4.1, reorder + bucket creation: `z` (depth-first keys) becomes shape-first and sorted;
// `table` (k slots) receives one bucket per shape. Returns n, the number of fragments.
std::uint32_t buildBuckets(std::span<std::uint32_t> z, std::span<std::uint32_t> table);

// H(b) = b mod k (Sec. 4.1, Eq. for H) with linear probing; the slot index, or nothing.
std::optional<std::uint32_t> findBucketSlot(std::span<const std::uint32_t> table, std::uint16_t shape);
std::optional<Bucket> findBucket(std::span<const std::uint32_t> table, std::uint16_t shape);

// Sec. 4.2, data pass: the index of `key` (shape-first) inside the bucket by binary search.
std::optional<std::uint32_t> findInBucket(std::span<const std::uint32_t> z, const Bucket& bucket, std::uint32_t key);

// One fragment as the neighbour query sees it.
struct QueryFragment {
  std::uint32_t key = kEmpty;  // shape-first
  glm::vec3 normal{0, 0, 1};
};

// seed 002, Sec. 5.1: ε = εn + εz with εn = 1 − n_i·n_j and εz = |z_i − z_j|² (z in [0, 1]).
float continuity(const QueryFragment& a, const QueryFragment& b);

enum class NeighborSearch { Buckets, BruteForce };

// A pixel of the CPU model: its n fragments (shape-first, sorted) and its bucket table.
struct ReferencePixel {
  std::vector<QueryFragment> fragments;
  std::vector<std::uint32_t> table;
};

// The best candidate for `f` among pixel q's fragments of the same shape: the bucket of that
// shape (Buckets) or every fragment of q filtered by shape (BruteForce, as in the illustration
// buffer). Ties go to the lower index. Returns the index in q, or nothing.
std::optional<std::uint32_t> bestCandidate(const QueryFragment& f, const ReferencePixel& q, NeighborSearch search);

// Fig. 5: the neighbour of fragment `i` of pixel p in pixel q, kept only when the reverse check
// (q's candidate picks i back among p's fragments) succeeds.
std::optional<std::uint32_t> neighborOf(const ReferencePixel& p, std::uint32_t i, const ReferencePixel& q,
                                        NeighborSearch search);

// Sec. 5.1: κ = tanh(κ1 + κ2) from view-facing neighbour normals (left, right, down, up),
// with κ1 + κ2 ≈ −scale·(∂nx/∂x + ∂ny/∂y) by central differences in pixels, so that convexities
// are negative; κ = −1 when a neighbour is missing.
float screenSpaceCurvature(const std::optional<glm::vec3>& left, const std::optional<glm::vec3>& right,
                           const std::optional<glm::vec3>& down, const std::optional<glm::vec3>& up, float scale);

}  // namespace tlab::render::kbuffer
