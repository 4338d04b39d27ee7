#pragma once
// statcheck: find APA-style test results in free text and recompute their p-values (after Nuijten,
// Hartgerink, van Assen, Epskamp & Wicherts 2016, "The prevalence of statistical reporting errors
// in psychology (1985-2013)", Behav. Res. Methods 48; and the R package statcheck 1.6.0, whose
// conventions are followed unless README.md lists a deliberate difference).
//
// Recognized (analysis/statcheck_scanner.hpp): t(df), r(df), Q(df) / Qw / Qwithin / Q-within / Qb /
// Qbetween / Q-between, F(df1, df2) (also F(l, df2): a letter l or I for a 1), χ²(df[, N = n])
// (chi2, chi_2, χ2, X2, x2, \chi^2, chi-square), and z / Z without df; then "=", "<" or ">" and the
// value (thousands separators allowed, any 1-3 stray symbols before it read as a minus sign),
// a comma, and "p <op> value" (also ".5e-3") or "ns".
//
// Rules (statcheck's, R/compute_p.R, R/error_test.R, R/decision_error_test.R):
//  - p is recomputed from the statistic and df: two-tailed for t, r (via t = r·√(df/(1−r²))) and z;
//    upper tail for F, χ² and Q. With `oneTailedTests` t, r and z are one-tailed.
//  - Rounding: a statistic printed with d decimals stands for [x − ½·10^-d, x + ½·10^-d]; the
//    recomputed p is therefore a range [low, up]. With the statistic reported with "=":
//    "p = v" is consistent if the range meets v's rounding interval; "p < v" if low < v;
//    "p > v" if up > v; "ns" counts as "p > α". With "t < x" (so p ≥ up): "p = v" is an error if
//    v's interval lies below up, "p < v" if v < up, "p > v" never. With "t > x" (p ≤ low): "p = v"
//    is an error if v's interval lies above low, "p > v" if v > low, "p < v" never.
//  - p ≤ 0 ("p = .000") is an error unless `pZeroError` is off.
//  - Decision error: an error whose reported and recomputed (point) p fall on different sides of
//    α; `pEqualAlphaSignificant` says whether p = α counts as significant (statcheck's default).
//  - One-tailed: with `oneTailedText` on, an error in a text that says "one-sided", "one-tailed" or
//    "directional" (statcheck's extract_1tail) is re-checked one-tailed; if that removes the error,
//    the one-tailed p is the computed p. Off by default, as in statcheck.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/interval.hpp"

namespace tlab::analysis {

enum class PRelation { Less, Equal, Greater, NotSignificant };
std::string_view pRelationSymbol(PRelation relation);  // "<", "=", ">", "ns"

// Whether a recomputed p range agrees with a reported "p <relation> value" for a statistic
// reported with "=" (rules above).
bool reportedPConsistent(const Interval& computed, PRelation relation, const ReportedValue& p, double alpha = 0.05);

// statcheck's test_type values.
enum class StatisticKind { T, F, R, Z, ChiSquared, Q, Qw, Qb };
std::string_view statisticName(StatisticKind kind);  // "t", "F", "r", "Z", "Chi2", "Q", "Qw", "Qb"

enum class TestComparison { Less, Equal, Greater };
std::string_view comparisonSymbol(TestComparison comparison);

struct ApaResult {
  StatisticKind kind = StatisticKind::T;
  // statcheck's columns: t and r have only df2; F has df1 and df2; χ² and Q only df1; z none.
  // A missing df is NaN.
  double df1 = 0.0;
  double df2 = 0.0;
  TestComparison testComparison = TestComparison::Equal;
  ReportedValue statistic;
  PRelation pRelation = PRelation::Equal;
  ReportedValue p;   // unused for "ns"
  std::string text;  // the matched text, normalized
  std::size_t line = 0;
};

// A p-value anywhere in the text (statcheck's AllPValues list), "ns" included.
struct ReportedP {
  PRelation relation = PRelation::Equal;
  ReportedValue p;  // unused for "ns"
  std::size_t line = 0;
};

struct StatcheckOptions {
  double alpha = 0.05;
  bool pEqualAlphaSignificant = true;  // statcheck's pEqualAlphaSig
  bool pZeroError = true;              // "p = .000" is an error
  bool oneTailedTests = false;         // treat every t, r, z as one-tailed
  bool oneTailedText = false;          // statcheck's OneTailedTxt: one-tailed wording detection
  // statcheck's `stat`: the test types to report, by statcheck's names "t", "F", "cor", "chisq",
  // "Z", "Q" (Q includes Qw and Qb); empty: all.
  std::vector<std::string> tests;
};

// statcheck's `stat` name of a test type ("cor" for r, "chisq" for χ², "Q" for Q, Qw and Qb).
std::string_view statSelectionName(StatisticKind kind);
// Throws AnalysisError for a name that is none of the above.
void validateTestSelection(const std::vector<std::string>& tests);

struct StatcheckVerdict {
  ApaResult result;
  double pComputed = 0.0;  // from the printed statistic (one-tailed when `oneTailed`)
  Interval pRange;         // over the statistic's rounding interval, same tails
  bool consistent = true;  // statcheck's error = !consistent
  bool decisionError = false;
  bool oneTailed = false;              // pComputed is one-tailed (option or detected wording)
  bool consistentIfOneTailed = false;  // t, r, z with a two-tailed error: agrees one-tailed
  std::string note;
};

struct StatcheckReport {
  std::string source;
  std::vector<StatcheckVerdict> verdicts;
  std::vector<ReportedP> pValues;  // every p-value in the text
  bool oneTailedInText = false;
  std::size_t inconsistencies() const;
  std::size_t decisionErrors() const;
  std::size_t pValuesWithoutStatistic() const;
  // statcheck's APA factor: results with a full test / all p-values (NaN without p-values).
  double apaFactor() const;
};

StatcheckVerdict checkApaResult(const ApaResult& result, bool oneTailedInText, const StatcheckOptions& options = {});
StatcheckReport statcheck(std::string_view text, const std::string& source, const StatcheckOptions& options = {});
// Reads a text, PDF or HTML file (analysis/document_text.hpp) and checks it.
StatcheckReport statcheckFile(const std::string& path, const StatcheckOptions& options = {});

}  // namespace tlab::analysis
