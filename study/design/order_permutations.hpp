#pragma once
// Orders that are not squares: every permutation (complete counterbalancing, n! rows in
// lexicographic order) and seeded random permutations (Fisher-Yates with the portable
// SeededRandom, so an order is the same on every platform).
#include <cstdint>
#include <string>

#include "study/design/latin_square.hpp"

namespace tlab::study {

// n <= 8 (40320 rows); throws DesignError beyond.
OrderTable allPermutations(int n);

std::vector<int> seededRandomOrder(int n, std::uint64_t seed);

// A 64-bit mix of a seed and further values (splitmix64 steps): independent streams per participant.
std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t value);
std::uint64_t mixSeed(std::uint64_t seed, const std::string& text);

}  // namespace tlab::study
