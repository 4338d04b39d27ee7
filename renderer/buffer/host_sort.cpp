#include "renderer/buffer/host_sort.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/parallel_shares.hpp"

namespace tlab::render {

namespace {

// A fragment's sort key: the depth's bits (positive floats order like their bit patterns), the
// triangle, and where its record sits.
struct Key {
  std::uint32_t depth, triangle;
  std::size_t source;
};

// (depth, triangle); equal keys keep the order of their records (both sorts below are stable).
bool before(const Key& a, const Key& b) { return a.depth != b.depth ? a.depth < b.depth : a.triangle < b.triangle; }

constexpr std::size_t kInsertionSortMax = 32;        // longer lists: std::stable_sort
constexpr std::size_t kPixelsPerThreadMin = 16384;  // fewer pixels a thread cost more to start than they save

void insertionSort(std::vector<Key>& keys) {
  for (std::size_t i = 1; i < keys.size(); ++i) {
    const Key key = keys[i];
    std::size_t j = i;
    for (; j > 0 && before(key, keys[j - 1]); --j) keys[j] = keys[j - 1];
    keys[j] = key;
  }
}

float wordAsFloat(std::uint32_t word) {
  float f;
  std::memcpy(&f, &word, 4);
  return f;
}

void sortPixel(const UnsortedLists& in, const SortedLists& out, std::uint32_t pixel, std::vector<Key>& keys) {
  const std::uint32_t n = in.counts[pixel];
  const std::size_t base = in.heads[pixel];
  keys.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::size_t source = in.slotPlane > 0 ? i * in.slotPlane + pixel : base + i;
    keys[i] = {in.records[source * in.stride], in.records[source * in.stride + 1], source};
  }
  if (n <= kInsertionSortMax) insertionSort(keys);
  else std::stable_sort(keys.begin(), keys.end(), before);
  float stepX = 0.0f, stepY = 0.0f;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t* record = in.records + keys[i].source * in.stride;
    std::memcpy(out.records + (base + i) * in.stride, record, std::size_t(in.stride) * 4);
    if (out.colorPlane) out.colorPlane[base + i] = record[out.colorOffset];
    if (out.listSteps) {  // GLSL's max(step, abs(gradient))
      stepX = std::max(stepX, std::fabs(wordAsFloat(record[out.gradientOffset])));
      stepY = std::max(stepY, std::fabs(wordAsFloat(record[out.gradientOffset + 1])));
    }
  }
  if (out.listSteps) {
    out.listSteps[2 * std::size_t(pixel)] = stepX;
    out.listSteps[2 * std::size_t(pixel) + 1] = stepY;
  }
}

void sortPixels(const UnsortedLists& in, const SortedLists& out, std::size_t from, std::size_t to) {
  std::vector<Key> keys;
  for (std::size_t k = from; k < to; ++k) sortPixel(in, out, in.covered[k], keys);
}

}  // namespace

void sortListsOnHost(const UnsortedLists& in, const SortedLists& out, unsigned threads) {
  const std::size_t n = in.coveredCount;
  core::forEachShare(n, core::sharesFor(n, kPixelsPerThreadMin, threads),
                     [&](std::size_t from, std::size_t to, std::size_t) { sortPixels(in, out, from, to); });
}

}  // namespace tlab::render
