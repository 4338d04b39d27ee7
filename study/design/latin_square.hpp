#pragma once
// A cyclic Latin square of order n: row r, column c holds (r + c) mod n, so every level appears
// once in every row (participant order) and once in every column (position).
#include <vector>

namespace tlab::study {

using OrderTable = std::vector<std::vector<int>>;  // rows of level indices

// n >= 1. Throws DesignError for n < 1.
OrderTable cyclicLatinSquare(int n);

// True when every row and every column holds each of 0..n-1 exactly once.
bool isLatinSquare(const OrderTable& square);

}  // namespace tlab::study
