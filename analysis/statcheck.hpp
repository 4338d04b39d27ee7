#pragma once
// statcheck: find APA-style test results in free text and recompute their p-values (after Nuijten,
// Hartgerink, van Assen, Epskamp & Wicherts 2016, "The prevalence of statistical reporting errors
// in psychology (1985-2013)", Behav. Res. Methods 48; and the R package statcheck).
//
// Recognized: t(df) = x, F(df1, df2) = x, χ²(df) = x (also written chi2, chi-square, X2, χ2,
// \chi^2, with an optional ", N = n" inside the parentheses), each followed by p = / < / > value or
// "ns". Unicode minus/dashes and line breaks from PDF extraction are normalized first.
//
// Rules (statcheck's):
//  - p is recomputed from the statistic and df: two-tailed for t, upper tail for F and χ².
//  - Rounding: a statistic printed with d decimals stands for [x - ½·10^-d, x + ½·10^-d]; the
//    recomputed p therefore is a range. "p = v" is consistent if that range meets the rounding
//    interval of v; "p < v" if the smallest recomputed p is below v; "p > v" if the largest is above v;
//    "ns" if the largest is above α.
//  - "p = 0" / "p = .000" is always an inconsistency (a p-value cannot be zero; write p < .001).
//  - One-tailed: an inconsistent t result that would be consistent with half the two-tailed p is
//    counted consistent when the text mentions "one-tailed", "one-sided" or "directional
//    test/hypothesis/prediction" (statcheck's OneTailedInTxt, which takes any "directional");
//    otherwise it is flagged with that remark.
//  - Decision error: an inconsistency that changes significance at α = .05 (reported p ≤ .05 but
//    recomputed p ≥ .05, or the reverse); p = .05 counts as significant (statcheck's default).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/interval.hpp"

namespace tlab::analysis {

enum class PRelation { Less, Equal, Greater, NotSignificant };
std::string_view pRelationSymbol(PRelation relation);  // "<", "=", ">", "ns"

// Whether a recomputed p range agrees with a reported "p <relation> value" (rules above).
bool reportedPConsistent(const Interval& computed, PRelation relation, const ReportedValue& p, double alpha = 0.05);

enum class StatisticKind { T, F, ChiSquared };
std::string_view statisticName(StatisticKind kind);  // "t", "F", "chi2"

struct ApaResult {
  StatisticKind kind = StatisticKind::T;
  double df1 = 0.0;
  double df2 = 0.0;  // F only
  ReportedValue statistic;
  PRelation pRelation = PRelation::Equal;
  ReportedValue p;   // unused for "ns"
  std::string text;  // the matched text, normalized
  std::size_t line = 0;
};

struct StatcheckVerdict {
  ApaResult result;
  double pComputed = 0.0;  // from the printed statistic
  Interval pRange;         // over the statistic's rounding interval
  bool consistent = true;
  bool decisionError = false;
  bool consistentIfOneTailed = false;  // t only: agrees with the one-tailed p
  std::string note;
};

struct StatcheckReport {
  std::string source;
  std::vector<StatcheckVerdict> verdicts;
  std::size_t pValuesWithoutStatistic = 0;  // "p = .05" with no recognizable test in front
  bool oneTailedInText = false;
  std::size_t inconsistencies() const;
  std::size_t decisionErrors() const;
};

std::vector<ApaResult> extractApaResults(std::string_view text);
StatcheckVerdict checkApaResult(const ApaResult& result, bool oneTailedInText, double alpha = 0.05);
StatcheckReport statcheck(std::string_view text, const std::string& source, double alpha = 0.05);
StatcheckReport statcheckFile(const std::string& path, double alpha = 0.05);

}  // namespace tlab::analysis
