#pragma once
// Tail probabilities of the reference distributions used by the tests (Student t, Fisher F,
// chi-squared, standard normal), all from Boost.Math. Upper tails always use
// boost::math::complement(...) so that small p-values are computed directly (down to the smallest
// normal double, ~1e-308) instead of as 1 - cdf, which would cancel to 0 below ~1e-16.
#include <string>
#include <string_view>

namespace tlab::analysis {

// The alternative hypothesis of a test, with R's names ("two.sided" is also accepted on input).
enum class Alternative { TwoSided, Less, Greater };

std::string_view alternativeName(Alternative alternative);  // "two-sided", "less", "greater"
Alternative parseAlternative(std::string_view text);         // throws AnalysisError

// p-value of an observed t on df degrees of freedom (df may be +inf: standard normal).
double studentTPValue(double t, double df, Alternative alternative);
// Quantile t_{df}(probability), e.g. probability = 0.975 for a two-sided 95 % interval.
double studentTQuantile(double probability, double df);
// P(T_df <= t) and P(T_df > t).
double studentTLowerTail(double t, double df);
double studentTUpperTail(double t, double df);

// P(F_{df1,df2} > f): the p-value of an ANOVA F ratio.
double fisherFUpperTail(double f, double df1, double df2);
// P(χ²_df > x).
double chiSquaredUpperTail(double x, double df);
// Standard normal tails and the p-value of a z statistic.
double normalLowerTail(double z);
double normalUpperTail(double z);
double normalPValue(double z, Alternative alternative);

}  // namespace tlab::analysis
