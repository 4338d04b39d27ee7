#include "analysis/nelder_mead.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

namespace {

using Point = std::vector<double>;

// c + t (p - c): the point on the line through the centroid c and p (t = -1: reflection of p).
Point along(const Point& c, const Point& p, double t) {
  Point out(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) out[i] = c[i] + t * (p[i] - c[i]);
  return out;
}

struct Simplex {
  std::vector<Point> points;
  std::vector<double> values;

  void sort() {
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    std::vector<Point> p;
    std::vector<double> v;
    for (const std::size_t i : order) {
      p.push_back(points[i]);
      v.push_back(values[i]);
    }
    points = std::move(p);
    values = std::move(v);
  }
  // Centroid of all points but the worst.
  Point centroid() const {
    Point c(points[0].size(), 0.0);
    for (std::size_t k = 0; k + 1 < points.size(); ++k)
      for (std::size_t i = 0; i < c.size(); ++i) c[i] += points[k][i] / static_cast<double>(points.size() - 1);
    return c;
  }
};

}  // namespace

NelderMeadResult nelderMeadMinimize(const std::function<double(const std::vector<double>&)>& f, std::vector<double> start,
                                    const NelderMeadOptions& options) {
  if (start.empty()) throw AnalysisError("Nelder-Mead needs at least one parameter");
  NelderMeadResult result;
  const auto eval = [&](const Point& p) {
    ++result.evaluations;
    const double v = f(p);
    return std::isnan(v) ? INFINITY : v;
  };
  Simplex s;
  s.points.push_back(start);
  for (std::size_t i = 0; i < start.size(); ++i) {
    Point p = start;
    const double step = i < options.initialStep.size() ? options.initialStep[i] : (start[i] != 0 ? 0.1 * std::fabs(start[i]) : 0.1);
    p[i] += step;
    s.points.push_back(p);
  }
  for (const auto& p : s.points) s.values.push_back(eval(p));
  while (result.evaluations < options.maxEvaluations) {
    s.sort();
    if (std::fabs(s.values.back() - s.values.front()) < options.tolerance) {
      result.converged = true;
      break;
    }
    const Point c = s.centroid();
    const Point r = along(c, s.points.back(), -1.0);
    const double fr = eval(r);
    if (fr < s.values.front()) {
      const Point e = along(c, s.points.back(), -2.0);
      const double fe = eval(e);
      s.points.back() = fe < fr ? e : r;
      s.values.back() = std::min(fe, fr);
      continue;
    }
    if (fr < s.values[s.values.size() - 2]) {
      s.points.back() = r;
      s.values.back() = fr;
      continue;
    }
    // Contraction: outside (towards r) when r beats the worst, else inside.
    const bool outside = fr < s.values.back();
    const Point k = along(c, s.points.back(), outside ? -0.5 : 0.5);
    const double fk = eval(k);
    if (fk < (outside ? fr : s.values.back())) {
      s.points.back() = k;
      s.values.back() = fk;
      continue;
    }
    for (std::size_t j = 1; j < s.points.size(); ++j) {  // shrink towards the best
      s.points[j] = along(s.points[0], s.points[j], 0.5);
      s.values[j] = eval(s.points[j]);
    }
  }
  s.sort();
  result.x = s.points.front();
  result.value = s.values.front();
  return result;
}

}  // namespace tlab::analysis
