#pragma once
// A Graeco-Latin square of order n: two Latin squares L1 (first factor) and L2 (second factor)
// superimposed so that every pair (L1[r][c], L2[r][c]) occurs exactly once (orthogonality). Row r
// is a participant group, column c a position: each group meets each level of both factors once,
// each position holds each level of both factors once, and each combination occurs once.
//   odd n:      L1 = (r + c) mod n, L2 = (2r + c) mod n   (orthogonal because 2 is invertible mod n)
//   n = 4, 8:   L1 = r ⊕ c, L2 = (α·r) ⊕ c over GF(2^k)   (α a generator, α ≠ 0, 1)
// None exists for n = 2 and 6 (Euler; Tarry 1900); other even orders are not built here.
#include "study/design/latin_square.hpp"

namespace tlab::study {

struct GraecoLatinSquare {
  OrderTable latin;  // first factor's level per (row, position)
  OrderTable greek;  // second factor's level per (row, position)
};

// Throws DesignError for orders with no (or no supported) construction.
GraecoLatinSquare graecoLatinSquare(int n);

// Both are Latin squares and every pair occurs exactly once.
bool isGraecoLatin(const GraecoLatinSquare& square);

}  // namespace tlab::study
