#pragma once
// Ranks with ties, as R's rank(ties.method = "average"): tied values share the mean of the ranks
// they occupy. Ties are exact equality of the doubles (R's default digits.rank = Inf).
#include <cstddef>
#include <span>
#include <vector>

namespace tlab::analysis {

struct Ranking {
  std::vector<double> ranks;             // 1-based midranks, in input order
  std::vector<std::size_t> tieSizes;     // size t of every group of tied values (t ≥ 2 only)
  bool hasTies() const { return !tieSizes.empty(); }
  double tieCorrectionSum() const;        // Σ (t³ - t) over tie groups
};

Ranking rankWithTies(std::span<const double> values);

}  // namespace tlab::analysis
