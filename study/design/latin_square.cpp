#include "study/design/latin_square.hpp"

#include "study/design/design_error.hpp"

namespace tlab::study {

OrderTable cyclicLatinSquare(int n) {
  if (n < 1) throw DesignError("a Latin square needs at least one level");
  OrderTable square(std::size_t(n), std::vector<int>(std::size_t(n), 0));
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) square[r][c] = (r + c) % n;
  return square;
}

bool isLatinSquare(const OrderTable& square) {
  const std::size_t n = square.size();
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<int> rowSeen(n, 0), columnSeen(n, 0);
    if (square[i].size() != n) return false;
    for (std::size_t j = 0; j < n; ++j) {
      const int a = square[i][j], b = square[j].size() == n ? square[j][i] : -1;
      if (a < 0 || a >= int(n) || b < 0 || b >= int(n) || rowSeen[a]++ || columnSeen[b]++) return false;
    }
  }
  return true;
}

}  // namespace tlab::study
