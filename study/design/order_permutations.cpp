#include "study/design/order_permutations.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "core/seeded_random.hpp"
#include "study/design/design_error.hpp"

namespace tlab::study {

OrderTable allPermutations(int n) {
  if (n < 1 || n > 8) throw DesignError("full permutation counterbalancing needs 1..8 conditions, not " + std::to_string(n));
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  OrderTable rows;
  do rows.push_back(order);
  while (std::next_permutation(order.begin(), order.end()));
  return rows;
}

std::vector<int> seededRandomOrder(int n, std::uint64_t seed) {
  std::vector<int> order(std::size_t(std::max(n, 0)));
  std::iota(order.begin(), order.end(), 0);
  core::SeededRandom random(seed);
  for (int i = n - 1; i > 0; --i) std::swap(order[std::size_t(i)], order[random.below(std::uint32_t(i + 1))]);
  return order;
}

std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t value) {
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ull * (value + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::uint64_t mixSeed(std::uint64_t seed, const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a
  for (const unsigned char c : text) h = (h ^ c) * 0x100000001b3ull;
  return mixSeed(seed, h);
}

}  // namespace tlab::study
