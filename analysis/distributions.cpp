#include "analysis/distributions.hpp"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

namespace {

bool isPositiveDf(double df) { return df > 0.0 && !std::isnan(df); }

void requireDf(double df, const char* what) {
  if (!isPositiveDf(df))
    throw AnalysisError(std::string(what) + " degrees of freedom must be positive, got " +
                        std::to_string(df));
}

}  // namespace

std::string_view alternativeName(Alternative alternative) {
  switch (alternative) {
    case Alternative::TwoSided: return "two-sided";
    case Alternative::Less: return "less";
    case Alternative::Greater: return "greater";
  }
  return "two-sided";
}

Alternative parseAlternative(std::string_view text) {
  if (text == "two-sided" || text == "two.sided" || text == "two_sided") return Alternative::TwoSided;
  if (text == "less") return Alternative::Less;
  if (text == "greater") return Alternative::Greater;
  throw AnalysisError("unknown alternative '" + std::string(text) +
                      "' (expected two-sided, less or greater)");
}

double studentTLowerTail(double t, double df) {
  requireDf(df, "t");
  if (std::isnan(t)) return std::nan("");
  if (std::isinf(t)) return t < 0 ? 0.0 : 1.0;
  if (std::isinf(df)) return normalLowerTail(t);
  return boost::math::cdf(boost::math::students_t(df), t);
}

double studentTUpperTail(double t, double df) {
  requireDf(df, "t");
  if (std::isnan(t)) return std::nan("");
  if (std::isinf(t)) return t > 0 ? 0.0 : 1.0;
  if (std::isinf(df)) return normalUpperTail(t);
  return boost::math::cdf(boost::math::complement(boost::math::students_t(df), t));
}

double studentTPValue(double t, double df, Alternative alternative) {
  switch (alternative) {
    case Alternative::Less: return studentTLowerTail(t, df);
    case Alternative::Greater: return studentTUpperTail(t, df);
    case Alternative::TwoSided:
      // 2·P(T > |t|), computed on the small tail so it never cancels.
      return std::min(1.0, 2.0 * studentTUpperTail(std::fabs(t), df));
  }
  return std::nan("");
}

double studentTQuantile(double probability, double df) {
  requireDf(df, "t");
  if (std::isinf(df)) return boost::math::quantile(boost::math::normal(), probability);
  return boost::math::quantile(boost::math::students_t(df), probability);
}

double fisherFUpperTail(double f, double df1, double df2) {
  requireDf(df1, "F numerator");
  requireDf(df2, "F denominator");
  if (std::isnan(f)) return std::nan("");
  if (std::isinf(f)) return 0.0;
  if (f <= 0.0) return 1.0;
  return boost::math::cdf(boost::math::complement(boost::math::fisher_f(df1, df2), f));
}

double chiSquaredUpperTail(double x, double df) {
  requireDf(df, "chi-squared");
  if (std::isnan(x)) return std::nan("");
  if (std::isinf(x)) return 0.0;
  if (x <= 0.0) return 1.0;
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(df), x));
}

double normalLowerTail(double z) {
  if (std::isnan(z)) return std::nan("");
  if (std::isinf(z)) return z < 0 ? 0.0 : 1.0;
  return boost::math::cdf(boost::math::normal(), z);
}

double normalUpperTail(double z) {
  if (std::isnan(z)) return std::nan("");
  if (std::isinf(z)) return z > 0 ? 0.0 : 1.0;
  return boost::math::cdf(boost::math::complement(boost::math::normal(), z));
}

double normalPValue(double z, Alternative alternative) {
  switch (alternative) {
    case Alternative::Less: return normalLowerTail(z);
    case Alternative::Greater: return normalUpperTail(z);
    case Alternative::TwoSided: return std::min(1.0, 2.0 * normalUpperTail(std::fabs(z)));
  }
  return std::nan("");
}

}  // namespace tlab::analysis
