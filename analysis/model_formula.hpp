#pragma once
// ModelFormula: the lme4 formula syntax of `tlab stats mixed` (Bates et al. 2015, JSS 67(1),
// Section 2.1, Table 2), parsed into its parts:
//   log(rt) ~ method * alpha + (1 + method | participant) + (1 | stimulus)
// - the response: a column, or log(column);
// - fixed-effect terms: `a + b`, `a:b` (interaction), `a * b` (= a + b + a:b, for any number of
//   factors), `1`/`0`/`-1` for the intercept; terms are ordered by degree as R's terms() does;
// - random-effect terms `(expr | g)`: expr is `1`, `x`, `1 + x`, `0 + x` (like lme4, `x` alone
//   keeps the intercept), g a column, `g1:g2` (the interaction of two columns) or `g1/g2`
//   (nested: g1 and g2:g1, lme4's names). `||` (uncorrelated slopes) is not supported.
#include <string>
#include <string_view>
#include <vector>

namespace tlab::analysis {

// One term of a linear predictor: the variables it multiplies, in the order written (empty:
// the intercept).
using ModelTerm = std::vector<std::string>;

struct LinearPredictor {
  bool intercept = true;
  std::vector<ModelTerm> terms;  // without the intercept, ordered by degree (stable)
};

struct RandomTerm {
  LinearPredictor expression;          // the columns of Z for each level of the grouping factor
  std::vector<std::string> grouping;   // one column, or several forming an interaction factor
};

struct ModelFormula {
  std::string text;
  std::string response;         // the column
  bool logResponse = false;     // log(column)
  LinearPredictor fixed;
  std::vector<RandomTerm> random;
  // Every column a term uses (fixed and random expressions), in order of first appearance.
  std::vector<std::string> variables() const;
};

// Throws AnalysisError naming the position of the problem ("formula: ... at character 12").
ModelFormula parseModelFormula(std::string_view text);

// "a:b" for a term, "(Intercept)" for the empty one.
std::string termLabel(const ModelTerm& term);
// "g" or "g1:g2".
std::string groupingLabel(const std::vector<std::string>& grouping);

}  // namespace tlab::analysis
