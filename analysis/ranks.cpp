#include "analysis/ranks.hpp"

#include <algorithm>
#include <numeric>

namespace tlab::analysis {

double Ranking::tieCorrectionSum() const {
  double sum = 0.0;
  for (const std::size_t t : tieSizes) {
    const double td = static_cast<double>(t);
    sum += td * td * td - td;
  }
  return sum;
}

Ranking rankWithTies(std::span<const double> values) {
  Ranking r;
  r.ranks.assign(values.size(), 0.0);
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i + 1;
    while (j < order.size() && values[order[j]] == values[order[i]]) ++j;
    const double midrank = (static_cast<double>(i + 1) + static_cast<double>(j)) / 2.0;
    for (std::size_t k = i; k < j; ++k) r.ranks[order[k]] = midrank;
    if (j - i > 1) r.tieSizes.push_back(j - i);
    i = j;
  }
  return r;
}

}  // namespace tlab::analysis
