// Mixed models against lme4/lmerTest: the data sets and values come from
// reference/mixed_models.R (R 4.2.2, lme4 1.1-31, lmerTest 3.1-3; tightened optimizer tolerances,
// so the reference is the optimum). Estimates and standard errors must agree within 1e-6
// relative for lmer and 1e-4 for glmer (the bounds); every test prints the largest relative
// difference per figure. The formula parser and the model matrices are checked against R's
// model.matrix column names.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/csv_reader.hpp"
#include "analysis/mixed_model.hpp"
#include "analysis/model_formula.hpp"
#include "analysis/model_matrix.hpp"
#include "tests/analysis/mixed_reference.hpp"
#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

using testing::MixedReference;
using testing::referencePath;
using testing::RelativeDifferences;

struct Case {
  const char* model;
  const char* file;
  const char* formula;
  MixedFamily family;
  bool reml;
  double tolerance;    // estimates and standard errors
  double dfTolerance;  // Satterthwaite df (numerical derivatives on both sides)
};

const FixedEffect* findTerm(const MixedModelResult& r, const std::string& term) {
  for (const auto& e : r.fixedEffects)
    if (e.term == term) return &e;
  return nullptr;
}

const VarianceComponent* findComponent(const MixedModelResult& r, const std::string& key) {
  for (const auto& v : r.randomEffects)
    if (v.group + "|" + v.term + "|" + v.term2 == key) return &v;
  return nullptr;
}

void compareWithR(const Case& c) {
  static const MixedReference reference;
  MixedModelRequest request;
  request.formula = c.formula;
  request.family = c.family;
  request.reml = c.reml;
  request.variables.factors = {"alpha"};  // slopes.csv: alpha is 0.3 or 0.6, a factor as in R
  const MixedModelResult r = fitMixedModel(readCsvFile(referencePath(c.file)), request);
  RelativeDifferences diff(c.model);
  const auto terms = reference.names(c.model, "fixed", "estimate");
  ASSERT_EQ(terms.size(), r.fixedEffects.size());
  for (const auto& term : terms) {
    const FixedEffect* e = findTerm(r, term);
    ASSERT_NE(e, nullptr) << "no coefficient " << term;
    diff.check("estimate", term, e->estimate, reference.at(c.model, "fixed", term, "estimate"), c.tolerance);
    diff.check("std_error", term, e->stdError, reference.at(c.model, "fixed", term, "std_error"), c.tolerance);
    if (c.family == MixedFamily::Gaussian)
      diff.check("df", term, e->df, reference.at(c.model, "fixed", term, "df"), c.dfTolerance);
    diff.check("p", term, e->p, reference.at(c.model, "fixed", term, "p"), 100 * c.dfTolerance);
    // lme4's default optimizer settings stop near the optimum; not asserted, printed.
    RelativeDifferences fromDefault(std::string(c.model) + " (lme4 default tolerances)");
    fromDefault.check("estimate", term, e->estimate, reference.at(c.model, "default", term, "estimate"), 1.0);
  }
  for (const auto& key : reference.names(c.model, "random", "variance")) {
    const VarianceComponent* v = findComponent(r, key);
    ASSERT_NE(v, nullptr) << "no variance component " << key;
    diff.check("variance", key, v->variance, reference.at(c.model, "random", key, "variance"), 10 * c.tolerance);
    const double sdCor = v->term2.empty() ? v->sd : v->correlation;
    diff.check("sd/correlation", key, sdCor, reference.at(c.model, "random", key, "sd_cor"), 10 * c.tolerance);
  }
  diff.check("log_likelihood", "", r.logLikelihood, reference.at(c.model, "fit", "", "log_likelihood"), c.tolerance * 1e-2);
  diff.check("aic", "", r.aic, reference.at(c.model, "fit", "", "aic"), c.tolerance * 1e-2);
  if (c.reml) diff.check("reml_criterion", "", r.remlCriterion, reference.at(c.model, "fit", "", "reml_criterion"), 1e-8);
  EXPECT_EQ(r.singular, reference.at(c.model, "fit", "", "singular") != 0.0);
  EXPECT_TRUE(r.converged);
}

TEST(MixedModelReference, CrossedInterceptsReml) {
  compareWithR({"crossed", "crossed.csv", "log(rt) ~ method + (1 | participant) + (1 | stimulus)", MixedFamily::Gaussian, true, 1e-6, 1e-4});
}

TEST(MixedModelReference, CrossedInterceptsMaximumLikelihood) {
  compareWithR({"crossed_ml", "crossed.csv", "log(rt) ~ method + (1 | participant) + (1 | stimulus)", MixedFamily::Gaussian, false, 1e-6, 1e-4});
}

TEST(MixedModelReference, CorrelatedRandomSlopes) {
  compareWithR({"slopes", "slopes.csv", "time ~ method * alpha + (1 + method | participant) + (1 | stimulus)", MixedFamily::Gaussian,
                true, 1e-6, 1e-4});
}

TEST(MixedModelReference, UnbalancedWithMissingCells) {
  compareWithR({"unbalanced", "unbalanced.csv", "score ~ condition + trial + (1 | participant) + (1 | item)", MixedFamily::Gaussian,
                true, 1e-6, 1e-4});
}

TEST(MixedModelReference, NestedAndCrossedGrouping) {
  compareWithR({"nested", "nested.csv", "grade ~ treatment + (1 | school/class) + (1 | rater)", MixedFamily::Gaussian, true, 1e-6, 1e-4});
}

TEST(MixedModelReference, LogisticCrossedIntercepts) {
  compareWithR({"binary_crossed", "binary_crossed.csv", "correct ~ method + (1 | participant) + (1 | stimulus)", MixedFamily::Binomial,
                false, 1e-4, 1e-4});
}

TEST(MixedModelReference, LogisticCorrelatedSlopeUnbalanced) {
  compareWithR({"binary_slopes", "binary_slopes.csv", "correct ~ layers + (1 + layers | participant) + (1 | stimulus)",
                MixedFamily::Binomial, false, 1e-4, 1e-4});
}

TEST(ModelFormula, ExpandsCrossingsAndOrdersTermsByDegree) {
  const ModelFormula f = parseModelFormula("log(rt) ~ a * b * c + d + (1 + a | p) + (1 | s/t)");
  EXPECT_EQ(f.response, "rt");
  EXPECT_TRUE(f.logResponse);
  std::vector<std::string> labels;
  for (const auto& t : f.fixed.terms) labels.push_back(termLabel(t));
  // R: attr(terms(~ a*b*c + d), "term.labels")
  EXPECT_EQ(labels, (std::vector<std::string>{"a", "b", "c", "d", "a:b", "a:c", "b:c", "a:b:c"}));
  ASSERT_EQ(f.random.size(), 3u);
  EXPECT_EQ(groupingLabel(f.random[0].grouping), "p");
  EXPECT_EQ(groupingLabel(f.random[1].grouping), "s");
  EXPECT_EQ(groupingLabel(f.random[2].grouping), "t:s");  // lme4's name for s/t
  EXPECT_TRUE(f.random[0].expression.intercept);
  EXPECT_FALSE(parseModelFormula("y ~ 0 + a + (0 + a | g)").fixed.intercept);
  EXPECT_TRUE(parseModelFormula("y ~ a + (a | g)").random[0].expression.intercept);  // lme4: (a | g) = (1 + a | g)
}

TEST(ModelFormula, RefusesWhatItCannotFit) {
  using testing::throwsWithMessage;
  EXPECT_TRUE(throwsWithMessage([] { parseModelFormula("y ~ a"); }, {"no random-effects term"}));
  EXPECT_TRUE(throwsWithMessage([] { parseModelFormula("y ~ a + (1 || g)"); }, {"'||'"}));
  EXPECT_TRUE(throwsWithMessage([] { parseModelFormula("y = a + (1|g)"); }, {"no '~'"}));
  EXPECT_TRUE(throwsWithMessage([] { parseModelFormula("sqrt(y) ~ a + (1|g)"); }, {"not a column"}));
}

TEST(ModelMatrix, ColumnNamesFollowRModelMatrix) {
  Table t("inline.csv", {"y", "a", "b", "g"});
  const char* rows[][4] = {{"1", "x", "u", "g1"}, {"2", "y", "u", "g1"}, {"3", "z", "v", "g2"}, {"4", "x", "v", "g2"},
                           {"5", "y", "v", "g3"}, {"6", "z", "u", "g3"}};
  std::size_t line = 2;
  for (const auto& r : rows) t.addRow({r[0], r[1], r[2], r[3]}, line++);
  const auto names = [&](const char* formula) {
    return buildMixedModelMatrices(t, parseModelFormula(formula), {}).xNames;
  };
  // R: colnames(model.matrix(~ a * b)) with levels in file order (x, y, z; u, v).
  EXPECT_EQ(names("y ~ a * b + (1|g)"), (std::vector<std::string>{"(Intercept)", "ay", "az", "bv", "ay:bv", "az:bv"}));
  // a:b without b's main effect: b is coded by indicators within a (R's rule).
  EXPECT_EQ(names("y ~ a + a:b + (1|g)"), (std::vector<std::string>{"(Intercept)", "ay", "az", "ax:bv", "ay:bv", "az:bv"}));
  EXPECT_EQ(names("y ~ 0 + a + (1|g)"), (std::vector<std::string>{"ax", "ay", "az"}));
  ModelVariables levels;
  levels.levels["a"] = {"z", "x", "y"};
  EXPECT_EQ(buildMixedModelMatrices(t, parseModelFormula("y ~ a + (1|g)"), levels).xNames,
            (std::vector<std::string>{"(Intercept)", "ax", "ay"}));
  const MixedModelMatrices m = buildMixedModelMatrices(t, parseModelFormula("y ~ a + (1 + b | g)"), {});
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].columns, (std::vector<std::string>{"(Intercept)", "bv"}));
  EXPECT_EQ(m.Z.cols(), 6);  // 3 levels × 2 columns
  EXPECT_EQ(m.thetaSize(), 3u);
}

TEST(MixedModel, SingularFitIsReportedAsLme4Does) {
  // No participant variance at all: the noise sums to zero within every participant, so all
  // participants have the same mean; lme4 estimates the participant variance as 0.
  Table t("singular.csv", {"y", "c", "p"});
  std::size_t line = 2;
  const double noise[4][3] = {{0.3, -0.5, 0.2}, {-0.4, 0.1, 0.3}, {0.6, -0.2, -0.4}, {-0.1, 0.5, -0.4}};
  for (int p = 0; p < 4; ++p)
    for (int s = 0; s < 3; ++s)
      t.addRow({std::to_string(10.0 + s + noise[p][s]), s == 0 ? "a" : "b", "p" + std::to_string(p)}, line++);
  const MixedModelResult r = fitMixedModel(t, {"y ~ c + (1|p)", MixedFamily::Gaussian, true, {}});
  EXPECT_TRUE(r.singular);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(std::find(r.warnings.begin(), r.warnings.end(), "boundary (singular) fit: see help('isSingular')"), r.warnings.end());
}

}  // namespace
}  // namespace tlab::analysis
