#include "study/design/graeco_latin_square.hpp"

#include <set>
#include <string>

#include "study/design/design_error.hpp"

namespace tlab::study {

namespace {

// Multiplication in GF(2^k) modulo the irreducible polynomial `modulus` (x²+x+1 = 0b111, x³+x+1 = 0b1011).
int gfMultiply(int a, int b, int k, int modulus) {
  int product = 0;
  for (; b; b >>= 1) {
    if (b & 1) product ^= a;
    a <<= 1;
    if (a & (1 << k)) a ^= modulus;
  }
  return product;
}

}  // namespace

GraecoLatinSquare graecoLatinSquare(int n) {
  if (n < 1) throw DesignError("a Graeco-Latin square needs at least one level");
  GraecoLatinSquare s;
  s.latin.assign(std::size_t(n), std::vector<int>(std::size_t(n)));
  s.greek = s.latin;
  if (n % 2 == 1) {
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        s.latin[r][c] = (r + c) % n;
        s.greek[r][c] = (2 * r + c) % n;
      }
    return s;
  }
  if (n == 4 || n == 8) {
    const int k = n == 4 ? 2 : 3, modulus = n == 4 ? 0b111 : 0b1011;
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        s.latin[r][c] = r ^ c;
        s.greek[r][c] = gfMultiply(2, r, k, modulus) ^ c;  // α = x (= 2) generates GF(2^k)*
      }
    return s;
  }
  if (n == 2 || n == 6) throw DesignError("no Graeco-Latin square of order " + std::to_string(n) + " exists (Euler/Tarry)");
  throw DesignError("Graeco-Latin squares are built for odd orders and 4 and 8, not " + std::to_string(n));
}

bool isGraecoLatin(const GraecoLatinSquare& square) {
  if (!isLatinSquare(square.latin) || !isLatinSquare(square.greek)) return false;
  std::set<std::pair<int, int>> pairs;
  for (std::size_t r = 0; r < square.latin.size(); ++r)
    for (std::size_t c = 0; c < square.latin.size(); ++c)
      if (!pairs.insert({square.latin[r][c], square.greek[r][c]}).second) return false;
  return true;
}

}  // namespace tlab::study
