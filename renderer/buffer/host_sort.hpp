#pragma once
// The sort pass (buffer/sort.comp, Carnecky Sec. 4.3) as host code, for where the GL runs on the
// CPU (issue #29): there llvmpipe gathers and scatters a storage buffer's words lane by lane, where
// host code copies each record whole. Each pixel's fragments go front to back into the block
// [heads[p], heads[p] + counts[p]) of the sorted records; ties in depth are broken by the triangle
// index, then by the order of the unsorted records, so the words written are the shader's.
// No GL here: the fragment buffer hands in its mapped buffers (FragmentBuffer::sortListsOnHost).
#include <cstddef>
#include <cstdint>

namespace tlab::render {

struct UnsortedLists {
  const std::uint32_t* records = nullptr;  // `stride` words a fragment; word 0 the depth's bits, word 1 the triangle
  std::uint32_t stride = 2;
  // 0: pixel p's records are the block at heads[p]; otherwise its i-th record is at i * slotPlane + p
  // (the slots of buffer/fill_slots.frag, slotPlane = the pixel count).
  std::size_t slotPlane = 0;
  const std::uint32_t* counts = nullptr;   // fragments of each pixel
  const std::uint32_t* heads = nullptr;    // each pixel's first place in the sorted records
  const std::uint32_t* covered = nullptr;  // the pixels that hold a fragment
  std::size_t coveredCount = 0;
};

struct SortedLists {
  // The sorted records, as many words a fragment as the unsorted (null: none, where a compositor
  // reads the colour plane alone).
  std::uint32_t* records = nullptr;
  // Each fragment's colour word again, in the sorted order (null: none); its word in the record.
  std::uint32_t* colorPlane = nullptr;
  std::uint32_t colorOffset = 0;
  // Each covered pixel's (max |∂z/∂x|, max |∂z/∂y|) over its list, two floats a pixel (null: none),
  // from the depth gradient's two words at `gradientOffset` of each record.
  float* listSteps = nullptr;
  std::uint32_t gradientOffset = 0;
};

// Sorts every covered pixel's list, the pixels shared out among `threads` threads (at least one;
// fewer where there are few pixels). Each pixel's words are written by one thread, so the result
// does not depend on how many there are.
void sortListsOnHost(const UnsortedLists& in, const SortedLists& out, unsigned threads);

}  // namespace tlab::render
