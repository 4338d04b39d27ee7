#include "study/design/williams_design.hpp"

#include "study/design/design_error.hpp"

namespace tlab::study {

OrderTable williamsDesign(int n) {
  if (n < 1) throw DesignError("a balanced Latin square needs at least one level");
  std::vector<int> first = {0};  // 0, 1, n-1, 2, n-2, ...: the steps 1, -2, 3, -4, ... are distinct mod n (even n)
  for (int k = 1, low = 1, high = n - 1; k < n; ++k) first.push_back(k % 2 == 1 ? low++ : high--);
  OrderTable rows;
  for (int r = 0; r < n; ++r) {
    std::vector<int> row;
    for (const int v : first) row.push_back((v + r) % n);
    rows.push_back(row);
  }
  if (n % 2 == 1) {
    const std::size_t m = rows.size();
    for (std::size_t r = 0; r < m; ++r) rows.emplace_back(rows[r].rbegin(), rows[r].rend());
  }
  return rows;
}

}  // namespace tlab::study
