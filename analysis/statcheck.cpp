#include "analysis/statcheck.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "analysis/analysis_error.hpp"
#include "analysis/distributions.hpp"
#include "analysis/document_text.hpp"
#include "analysis/statcheck_scanner.hpp"

namespace tlab::analysis {

std::string_view pRelationSymbol(PRelation relation) {
  switch (relation) {
    case PRelation::Less: return "<";
    case PRelation::Equal: return "=";
    case PRelation::Greater: return ">";
    case PRelation::NotSignificant: return "ns";
  }
  return "=";
}

std::string_view comparisonSymbol(TestComparison comparison) {
  switch (comparison) {
    case TestComparison::Less: return "<";
    case TestComparison::Equal: return "=";
    case TestComparison::Greater: return ">";
  }
  return "=";
}

std::string_view statisticName(StatisticKind kind) {
  switch (kind) {
    case StatisticKind::T: return "t";
    case StatisticKind::F: return "F";
    case StatisticKind::R: return "r";
    case StatisticKind::Z: return "Z";
    case StatisticKind::ChiSquared: return "Chi2";
    case StatisticKind::Q: return "Q";
    case StatisticKind::Qw: return "Qw";
    case StatisticKind::Qb: return "Qb";
  }
  return "t";
}

std::string_view statSelectionName(StatisticKind kind) {
  switch (kind) {
    case StatisticKind::R: return "cor";
    case StatisticKind::ChiSquared: return "chisq";
    case StatisticKind::Qw:
    case StatisticKind::Qb: return "Q";
    default: return statisticName(kind);
  }
}

void validateTestSelection(const std::vector<std::string>& tests) {
  static constexpr std::string_view names[] = {"t", "F", "cor", "chisq", "Z", "Q"};
  for (const auto& t : tests)
    if (std::find(std::begin(names), std::end(names), t) == std::end(names))
      throw AnalysisError("statcheck: unknown test type '" + t + "' (use t, F, cor, chisq, Z, Q)");
}

bool reportedPConsistent(const Interval& computed, PRelation relation, const ReportedValue& p, double alpha) {
  switch (relation) {
    case PRelation::Equal: return computed.intersects(p.interval());
    case PRelation::Less: return computed.lo < p.value;
    case PRelation::Greater: return computed.hi > p.value;
    case PRelation::NotSignificant: return computed.hi > alpha;
  }
  return false;
}

std::size_t StatcheckReport::inconsistencies() const {
  std::size_t n = 0;
  for (const auto& v : verdicts) n += v.consistent ? 0 : 1;
  return n;
}

std::size_t StatcheckReport::decisionErrors() const {
  std::size_t n = 0;
  for (const auto& v : verdicts) n += v.decisionError ? 1 : 0;
  return n;
}

std::size_t StatcheckReport::pValuesWithoutStatistic() const {
  return pValues.size() >= verdicts.size() ? pValues.size() - verdicts.size() : 0;
}

double StatcheckReport::apaFactor() const {
  if (pValues.empty()) return std::nan("");
  return static_cast<double>(verdicts.size()) / static_cast<double>(pValues.size());
}

namespace {

bool symmetricTest(StatisticKind kind) {
  return kind == StatisticKind::T || kind == StatisticKind::R || kind == StatisticKind::Z;
}

// p of |statistic| (R/compute_p.R): t, r and z two-tailed unless `oneTailed`; F, χ², Q upper tail.
double pAt(const ApaResult& r, double value, bool oneTailed) {
  const double tails = oneTailed ? 1.0 : 2.0;
  const double a = std::fabs(value);
  switch (r.kind) {
    case StatisticKind::T: return tails * studentTUpperTail(a, r.df2);
    case StatisticKind::R: {
      if (a >= 1.0) return 0.0;
      const double t = a / std::sqrt((1.0 - a * a) / r.df2);  // statcheck's r2t
      return tails * studentTUpperTail(t, r.df2);
    }
    case StatisticKind::Z: return tails * normalUpperTail(a);
    case StatisticKind::F: return value <= 0.0 ? 1.0 : fisherFUpperTail(value, r.df1, r.df2);
    case StatisticKind::ChiSquared:
    case StatisticKind::Q:
    case StatisticKind::Qw:
    case StatisticKind::Qb: return value <= 0.0 ? 1.0 : chiSquaredUpperTail(value, r.df1);
  }
  return std::nan("");
}

// p over the statistic's rounding interval; p falls as |statistic| grows.
Interval pRangeOf(const ApaResult& r, bool oneTailed) {
  Interval s = r.statistic.interval();
  if (symmetricTest(r.kind)) s = abs(s);
  return mapDecreasing(s, [&](double x) { return pAt(r, x, oneTailed); });
}

// statcheck's error_test.R with the rounding interval of the reported p (see statcheck.hpp).
bool isError(const ApaResult& r, const Interval& p, const StatcheckOptions& o) {
  if (r.pRelation != PRelation::NotSignificant && o.pZeroError && r.p.value <= 0.0) return true;
  const PRelation relation = r.pRelation == PRelation::NotSignificant ? PRelation::Greater : r.pRelation;
  ReportedValue reported = r.p;
  if (r.pRelation == PRelation::NotSignificant) reported = ReportedValue{o.alpha, 17, ""};
  switch (r.testComparison) {
    case TestComparison::Equal: return !reportedPConsistent(p, relation, reported, o.alpha);
    case TestComparison::Less:  // the statistic is below its value: p ≥ p.hi
      if (relation == PRelation::Equal) return reported.interval().hi < p.hi;
      if (relation == PRelation::Less) return reported.value < p.hi;
      return false;
    case TestComparison::Greater:  // p ≤ p.lo
      if (relation == PRelation::Equal) return reported.interval().lo > p.lo;
      if (relation == PRelation::Greater) return reported.value > p.lo;
      return false;
  }
  return false;
}

// statcheck's decision_error_test.R, on the point p computed from the printed statistic.
bool isDecisionError(const ApaResult& r, double computed, const StatcheckOptions& o) {
  const double a = o.alpha;
  const bool ns = r.pRelation == PRelation::NotSignificant;
  const double reported = ns ? a : r.p.value;
  const PRelation relation = ns ? PRelation::Greater : r.pRelation;
  const bool sigAtAlpha = o.pEqualAlphaSignificant;
  // "Reported significant" / "computed not significant" and the reverse, with p = α on the side
  // the option puts it.
  const bool repSig = sigAtAlpha ? reported <= a : reported < a;
  const bool compNonSig = sigAtAlpha ? computed > a : computed >= a;
  switch (r.testComparison) {
    case TestComparison::Equal:
      if (relation == PRelation::Equal) return (repSig && compNonSig) || (!repSig && !compNonSig);
      if (relation == PRelation::Less) return reported <= a && compNonSig;
      return reported >= a && !compNonSig;
    case TestComparison::Less:
      if (relation == PRelation::Greater) return false;
      if (relation == PRelation::Less) return reported <= a && computed >= a;
      return repSig && computed >= a;
    case TestComparison::Greater:
      if (relation == PRelation::Less) return false;
      if (relation == PRelation::Greater) return reported >= a && computed <= a;
      return !repSig && computed <= a;
  }
  return false;
}

std::string fmt(double x) {
  std::ostringstream out;
  out.precision(4);
  out << x;
  return out.str();
}

void evaluate(StatcheckVerdict& v, bool oneTailed, const StatcheckOptions& o) {
  v.oneTailed = oneTailed;
  v.pComputed = pAt(v.result, v.result.statistic.value, oneTailed);
  v.pRange = pRangeOf(v.result, oneTailed);
  v.consistent = !isError(v.result, v.pRange, o);
  v.decisionError = !v.consistent && isDecisionError(v.result, v.pComputed, o);
}

}  // namespace

StatcheckVerdict checkApaResult(const ApaResult& result, bool oneTailedInText, const StatcheckOptions& options) {
  StatcheckVerdict v;
  v.result = result;
  evaluate(v, options.oneTailedTests, options);
  if (!v.consistent && !options.oneTailedTests && symmetricTest(result.kind)) {
    StatcheckVerdict one = v;
    evaluate(one, true, options);
    v.consistentIfOneTailed = one.consistent;
    if (one.consistent && options.oneTailedText && oneTailedInText) {
      v = one;
      v.consistentIfOneTailed = true;
      v.note = "consistent as a one-tailed test (the text mentions one-tailed/one-sided/directional testing)";
    } else if (one.consistent) {
      v.note = oneTailedInText ? "consistent if one-tailed (the text mentions one-tailed testing; --one-tailed-text)"
                               : "would be consistent if one-tailed, but the text never says one-tailed";
    }
  }
  if (!v.consistent) {
    if (result.pRelation != PRelation::NotSignificant && result.p.value <= 0.0 && options.pZeroError)
      v.note = "a p-value cannot be 0 (report p < .001)";
    else if (v.note.empty())
      v.note = "recomputed p = " + fmt(v.pComputed) + " (range " + fmt(v.pRange.lo) + " to " + fmt(v.pRange.hi) +
               " over the rounding of the statistic)";
    if (v.decisionError) v.note += "; decision error at alpha = " + fmt(options.alpha);
  }
  return v;
}

StatcheckReport statcheck(std::string_view text, const std::string& source, const StatcheckOptions& options) {
  StatcheckReport report;
  report.source = source;
  const NormalizedText norm = normalizeForStatcheck(text);
  report.oneTailedInText = mentionsOneTailed(norm.text);
  validateTestSelection(options.tests);
  for (const auto& r : extractApaResults(norm)) {
    const auto name = statSelectionName(r.kind);
    if (!options.tests.empty() && std::find(options.tests.begin(), options.tests.end(), name) == options.tests.end())
      continue;
    report.verdicts.push_back(checkApaResult(r, report.oneTailedInText, options));
  }
  report.pValues = extractPValues(norm);
  return report;
}

StatcheckReport statcheckFile(const std::string& path, const StatcheckOptions& options) {
  return statcheck(readDocumentText(path), path, options);
}

}  // namespace tlab::analysis
