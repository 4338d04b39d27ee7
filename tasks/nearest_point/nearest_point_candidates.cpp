// The choice of NearestPointTask's candidates (nearest_point_candidates.hpp).
#include "tasks/nearest_point/nearest_point_candidates.hpp"

#include <algorithm>

namespace tlab::tasks::nearest {

namespace {

// The ratio second-smallest / smallest − 1 (the margin by which the smallest is unique).
double uniquenessMargin(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[0] > 0.0 ? v[1] / v[0] - 1.0 : 0.0;
}

}  // namespace

std::size_t argMin(const std::vector<double>& v) { return std::size_t(std::min_element(v.begin(), v.end()) - v.begin()); }

std::optional<Choice> chooseCandidates(std::vector<PoolPoint> pool, int count, double margin, bool wantTrap,
                                       double pixelGap, core::SeededRandom& random) {
  for (std::size_t i = pool.size(); i > 1; --i) std::swap(pool[i - 1], pool[random.below(std::uint32_t(i))]);
  const auto apart = [&](const PoolPoint& p, const std::vector<PoolPoint>& chosen) {
    for (const auto& c : chosen)
      if (glm::length(c.pixel - p.pixel) < pixelGap) return false;
    return true;
  };
  for (const auto& g : pool) {
    if (!g.exact) continue;  // the nearest must be known exactly; the others only need to be far enough
    std::vector<PoolPoint> chosen = {g};
    double euclideanLimit = g.euclidean;  // the others must be farther than this in 3-D
    if (wantTrap) {
      for (const auto& e : pool)
        if (e.geodesic >= (1.0 + margin) * g.geodesic && (1.0 + margin) * e.euclidean <= g.euclidean && apart(e, chosen)) {
          chosen.push_back(e);
          euclideanLimit = (1.0 + margin) * e.euclidean;
          break;
        }
      if (chosen.size() < 2) continue;
    }
    for (const auto& o : pool) {
      if (int(chosen.size()) == count) break;
      if (o.geodesic >= (1.0 + margin) * g.geodesic && o.euclidean > euclideanLimit && apart(o, chosen)) chosen.push_back(o);
    }
    if (int(chosen.size()) < count) continue;
    // Shuffle so that the label says nothing about which candidate is nearest.
    for (std::size_t i = chosen.size(); i > 1; --i) std::swap(chosen[i - 1], chosen[random.below(std::uint32_t(i))]);
    Choice c;
    std::vector<double> geo, euc;
    for (const auto& p : chosen) geo.push_back(p.geodesic), euc.push_back(p.euclidean);
    c.candidates = std::move(chosen);
    c.geodesicMargin = uniquenessMargin(geo);
    c.euclideanMargin = uniquenessMargin(euc);
    c.trap = argMin(geo) != argMin(euc);
    return c;
  }
  return std::nullopt;
}

std::vector<double> headBounds(const std::vector<double>& upper, const std::vector<double>& straight, double margin, bool trap) {
  std::vector<double> heads;
  for (std::size_t g = 0; g < upper.size(); ++g) {
    bool ok = !trap;
    for (std::size_t e = 0; e < upper.size() && !ok; ++e)
      ok = e != g && (1.0 + margin) * straight[e] <= straight[g] && upper[e] >= (1.0 + margin) * straight[g];
    if (ok) heads.push_back(upper[g]);
  }
  std::sort(heads.begin(), heads.end());
  return heads;
}

}  // namespace tlab::tasks::nearest
