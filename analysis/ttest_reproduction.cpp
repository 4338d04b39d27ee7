#include "analysis/ttest_reproduction.hpp"

#include <cmath>
#include <limits>

#include "analysis/distributions.hpp"

namespace tlab::analysis {

namespace {

// One-sided p = P(T_df < -|t|); decreasing in |t|, and for a fixed negative t increasing as df
// falls (heavier tails), so the corners below enclose p over the whole box.
Interval pRangeOf(Interval absT, Interval df, int tails) {
  const double k = tails == 1 ? 1.0 : 2.0;
  return {k * studentTLowerTail(-absT.hi, df.hi), k * studentTLowerTail(-absT.lo, df.lo)};
}

// Welch df = (a + b)² / (a²/(n1-1) + b²/(n2-1)) with a = v1/n1, b = v2/n2 depends on ρ = b/a only:
// g(ρ) = (1 + ρ)² / (c1 + c2 ρ²), c = 1/(n - 1), rises on [0, c1/c2] to its maximum
// 1/c1 + 1/c2 = n1 + n2 - 2 (Cauchy-Schwarz) and falls after; its exact range over the box follows
// from the range of ρ (no interval-dependency overestimate).
Interval welchDfRange(Interval v1, Interval v2, double n1, double n2) {
  const double c1 = 1.0 / (n1 - 1.0), c2 = 1.0 / (n2 - 1.0);
  const auto g = [&](double rho) { return (1 + rho) * (1 + rho) / (c1 + c2 * rho * rho); };
  const Interval rho = (v2 / Interval::point(n2)) / (v1 / Interval::point(n1));
  const double lo = std::min(g(rho.lo), g(rho.hi));
  const double hi = rho.contains(c1 / c2) ? n1 + n2 - 2.0 : std::max(g(rho.lo), g(rho.hi));
  return {lo, hi};
}

// The variance of the mean difference under each hypothesis, over the box.
Interval standardErrorSquared(const PrintedTTest& c, TTestKind kind) {
  const Interval n1 = Interval::point(c.n1), n2 = Interval::point(c.n2);
  if (kind == TTestKind::Welch) return c.variance1Range / n1 + c.variance2Range / n2;
  // Student: pooled s² = ((n1-1)v1 + (n2-1)v2)/(n1+n2-2), times 1/n1 + 1/n2 (all increasing in v).
  const Interval pooled = (Interval::point(c.n1 - 1) * c.variance1Range + Interval::point(c.n2 - 1) * c.variance2Range) /
                          Interval::point(c.n1 + c.n2 - 2);
  return pooled * Interval::point(1.0 / c.n1 + 1.0 / c.n2);
}

void setConsistency(const PrintedTTest& c, TTestHypothesisCheck& check) {
  check.dfConsistent = !c.df || check.dfRange.intersects(c.df->interval());
  check.tConsistent = !c.t || check.absTRange.intersects(abs(c.t->interval()));
  check.pConsistent = !c.p || check.pRange.intersects(c.p->interval());
}

}  // namespace

TTestHypothesisCheck checkTwoSampleHypothesis(const PrintedTTest& c, TTestKind kind) {
  const SampleSummary x{static_cast<std::size_t>(c.n1), c.mean1.value, c.variance1};
  const SampleSummary y{static_cast<std::size_t>(c.n2), c.mean2.value, c.variance2};
  const TTestResult r = kind == TTestKind::Welch ? welchTTestFromSummaries(x, y, Alternative::Less)
                                                 : studentTTestFromSummaries(x, y, Alternative::Less);
  TTestHypothesisCheck check;
  check.kind = kind;
  check.t = r.t;
  check.df = r.df;
  check.pOneSided = studentTLowerTail(-std::fabs(r.t), r.df);
  const Interval diff = abs(c.mean1.interval() - c.mean2.interval());
  check.absTRange = diff / sqrt(standardErrorSquared(c, kind));
  check.dfRange = kind == TTestKind::Welch ? welchDfRange(c.variance1Range, c.variance2Range, c.n1, c.n2)
                                           : Interval::point(c.n1 + c.n2 - 2);
  check.pRange = pRangeOf(check.absTRange, check.dfRange, c.pTails);
  setConsistency(c, check);
  return check;
}

TTestHypothesisCheck checkPairedHypothesis(const PrintedTTest& c) {
  const double n = c.n1;
  TTestHypothesisCheck check;
  check.kind = TTestKind::Paired;
  check.t = std::nan("");
  check.df = n - 1;
  check.dfRange = Interval::point(n - 1);
  check.absTRange = {0.0, std::numeric_limits<double>::infinity()};  // any |t|, for some r
  check.pRange = {0.0, c.pTails == 1 ? 0.5 : 1.0};
  check.pOneSided = std::nan("");
  setConsistency(c, check);
  check.dfConsistent = check.dfConsistent && c.n1 == c.n2;
  check.impliedCorrelation = std::nan("");
  check.impliedCorrelationRange = {std::nan(""), std::nan("")};
  if (!c.t || c.n1 != c.n2 || c.t->value == 0.0) return check;
  const double d = c.mean1.value - c.mean2.value;
  const double t = c.t->value;
  const double v1 = c.variance1, v2 = c.variance2;
  check.impliedCorrelation = (v1 + v2 - n * d * d / (t * t)) / (2 * std::sqrt(v1 * v2));
  const Interval d2 = square(c.mean1.interval() - c.mean2.interval());
  const Interval t2 = square(c.t->interval());
  if (t2.contains(0.0)) return check;
  const Interval numerator = c.variance1Range + c.variance2Range - Interval::point(n) * d2 / t2;
  check.impliedCorrelationRange = numerator / (Interval::point(2.0) * sqrt(c.variance1Range * c.variance2Range));
  return check;
}

}  // namespace tlab::analysis
