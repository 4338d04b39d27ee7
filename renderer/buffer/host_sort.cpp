#include "renderer/buffer/host_sort.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/parallel_shares.hpp"

namespace tlab::render {

namespace {

// A fragment's sort key: the depth's bits (positive floats order like their bit patterns), the
// triangle, and its place in the pixel's unsorted list (the order of its record in memory, for
// slots and blocks alike). The three make every key distinct, so any sort of them gives one
// order: the shader's stable sort by (depth, triangle).
struct Key {
  std::uint32_t depth, triangle, place;
};

bool before(const Key& a, const Key& b) {
  if (a.depth != b.depth) return a.depth < b.depth;
  return a.triangle != b.triangle ? a.triangle < b.triangle : a.place < b.place;
}

constexpr std::size_t kInsertionSortMax = 32;        // longer lists: std::sort
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

std::size_t sourceOf(const UnsortedLists& in, std::uint32_t pixel, std::uint32_t place) {
  return in.slotPlane > 0 ? place * in.slotPlane + pixel : std::size_t(in.heads[pixel]) + place;
}

// Sorts one pixel's keys. Adjacent pixels mostly see the same surfaces arrive in the same order,
// so where the last list this thread had to sort was as long, the keys are read in the order
// that sorted it (`hint`, its places front to back). The list is then usually sorted as read,
// which n - 1 comparisons show, and otherwise nearly so for the insertion sort. (On the 16-layer
// stack, whose quads arrive in random depth order, each list read in place order took about 60
// moves; issue #29.)
void sortKeys(const UnsortedLists& in, std::uint32_t pixel, std::vector<Key>& keys, std::vector<std::uint32_t>& hint) {
  const std::uint32_t n = in.counts[pixel];
  keys.resize(n);
  const bool hinted = hint.size() == n;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t place = hinted ? hint[i] : i;
    const std::uint32_t* record = in.records + sourceOf(in, pixel, place) * in.stride;
    keys[i] = {record[0], record[1], place};
  }
  if (std::is_sorted(keys.begin(), keys.end(), before)) return;
  if (n <= kInsertionSortMax) insertionSort(keys);
  else std::sort(keys.begin(), keys.end(), before);
  hint.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) hint[i] = keys[i].place;
}

void sortPixel(const UnsortedLists& in, const SortedLists& out, std::uint32_t pixel, std::vector<Key>& keys,
               std::vector<std::uint32_t>& hint) {
  sortKeys(in, pixel, keys, hint);
  const std::size_t base = in.heads[pixel];
  float stepX = 0.0f, stepY = 0.0f;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::uint32_t* record = in.records + sourceOf(in, pixel, keys[i].place) * in.stride;
    if (out.records) std::memcpy(out.records + (base + i) * in.stride, record, std::size_t(in.stride) * 4);
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
  std::vector<std::uint32_t> hint;
  for (std::size_t k = from; k < to; ++k) sortPixel(in, out, in.covered[k], keys, hint);
}

}  // namespace

void sortListsOnHost(const UnsortedLists& in, const SortedLists& out, unsigned threads) {
  const std::size_t n = in.coveredCount;
  core::forEachShare(n, core::sharesFor(n, kPixelsPerThreadMin, threads),
                     [&](std::size_t from, std::size_t to, std::size_t) { sortPixels(in, out, from, to); });
}

}  // namespace tlab::render
