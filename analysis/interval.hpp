#pragma once
// Interval arithmetic for published, rounded numbers. A value printed as 0.234 stands for every
// real number that rounds to it, [0.2335, 0.2345]; pushing such intervals through a formula with
// outward-enclosing operations (Moore 1966, Interval Analysis) gives a range guaranteed to contain
// the value the authors computed from their unrounded data. A hypothesis (e.g. "they used
// Welch's test") is consistent with a table when every recomputed range meets the published
// number's own rounding interval.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

namespace tlab::analysis {

struct Interval {
  double lo = 0.0;
  double hi = 0.0;

  static Interval point(double x) { return {x, x}; }
  bool contains(double x) const { return lo <= x && x <= hi; }
  bool intersects(const Interval& o) const { return lo <= o.hi && o.lo <= hi; }
  double mid() const { return 0.5 * (lo + hi); }
};

inline Interval operator+(Interval a, Interval b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline Interval operator-(Interval a, Interval b) { return {a.lo - b.hi, a.hi - b.lo}; }
inline Interval operator*(Interval a, Interval b) {
  const double p[] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
inline Interval operator/(Interval a, Interval b) {
  if (b.contains(0.0)) throw std::domain_error("interval division by an interval containing 0");
  return a * Interval{1.0 / b.hi, 1.0 / b.lo};
}
inline Interval operator*(double c, Interval a) { return Interval::point(c) * a; }
inline Interval abs(Interval a) {
  if (a.lo >= 0) return a;
  if (a.hi <= 0) return {-a.hi, -a.lo};
  return {0.0, std::max(-a.lo, a.hi)};
}
inline Interval square(Interval a) {
  const Interval m = abs(a);
  return {m.lo * m.lo, m.hi * m.hi};
}
inline Interval sqrt(Interval a) { return {std::sqrt(std::max(0.0, a.lo)), std::sqrt(a.hi)}; }
// Image of an interval under a monotone increasing / decreasing function.
template <class F>
Interval mapIncreasing(Interval a, F f) { return {f(a.lo), f(a.hi)}; }
template <class F>
Interval mapDecreasing(Interval a, F f) { return {f(a.hi), f(a.lo)}; }

// A number as printed in a paper: its value and how many decimals were printed.
struct ReportedValue {
  double value = 0.0;
  int decimals = 0;
  std::string text;

  // "0.234" → value 0.234, 3 decimals; ".068" → 3 decimals; "140.0" → 1 decimal.
  static ReportedValue parse(std::string_view printed) {
    ReportedValue r;
    r.text = std::string(printed);
    // Any whitespace may sit between a sign and its digits ("−\n2.66" from a PDF's line break).
    std::string clean;
    for (const char c : printed)
      if (!std::isspace(static_cast<unsigned char>(c))) clean.push_back(c);
    r.value = std::stod(clean);
    const auto dot = clean.find('.');
    const auto exponent = clean.find_first_of("eE");
    if (dot != std::string::npos)
      r.decimals = static_cast<int>((exponent == std::string::npos ? clean.size() : exponent) - dot - 1);
    return r;
  }
  // Every value that rounds to the printed one (half a unit of the last printed digit either way).
  Interval interval() const {
    const double half = 0.5 * std::pow(10.0, -decimals);
    return {value - half, value + half};
  }
};

// x rounded to `decimals` decimals (half away from zero).
inline double roundToDecimals(double x, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(x * scale) / scale;
}

}  // namespace tlab::analysis
