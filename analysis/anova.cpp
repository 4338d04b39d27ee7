#include "analysis/anova.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <sstream>
#include <tuple>

#include "analysis/analysis_error.hpp"
#include "analysis/contrasts.hpp"
#include "analysis/distributions.hpp"
#include "analysis/r_moments.hpp"

namespace tlab::analysis {

namespace {

using Mask = unsigned;  // a term as the set of factors it involves

// All subsets of n factors, the empty term first, then by order (main effects, 2-way, ...).
std::vector<Mask> allTerms(std::size_t n) {
  std::vector<Mask> terms;
  for (Mask m = 0; m < (Mask{1} << n); ++m) terms.push_back(m);
  std::stable_sort(terms.begin(), terms.end(),
                   [](Mask a, Mask b) { return std::popcount(a) < std::popcount(b); });
  return terms;
}

bool isSubset(Mask a, Mask b) { return (a & ~b) == 0; }

// Columns of one between term, sum-to-zero coded: for each subject the product of its factors'
// codings (the row-wise Kronecker product); the empty term is the intercept column of ones.
Eigen::MatrixXd betweenTermColumns(const AnovaDesign& design, Mask term) {
  const auto n = static_cast<Eigen::Index>(design.subjects.size());
  Eigen::MatrixXd columns = Eigen::MatrixXd::Ones(n, 1);
  for (std::size_t f = 0; f < design.between.size(); ++f) {
    if (!(term & (Mask{1} << f))) continue;
    const Eigen::MatrixXd coding = sumToZeroCoding(design.between[f].levels.size());
    Eigen::MatrixXd next(n, columns.cols() * coding.cols());
    for (Eigen::Index s = 0; s < n; ++s) {
      const auto level = static_cast<Eigen::Index>(design.betweenLevels[static_cast<std::size_t>(s)][f]);
      for (Eigen::Index i = 0; i < columns.cols(); ++i)
        for (Eigen::Index j = 0; j < coding.cols(); ++j)
          next(s, i * coding.cols() + j) = columns(s, i) * coding(level, j);
    }
    columns = std::move(next);
  }
  return columns;
}

Eigen::MatrixXd modelMatrix(const std::vector<Eigen::MatrixXd>& termColumns,
                            const std::vector<std::size_t>& terms, Eigen::Index rows) {
  Eigen::Index cols = 0;
  for (const std::size_t t : terms) cols += termColumns[t].cols();
  Eigen::MatrixXd x(rows, cols);
  Eigen::Index c = 0;
  for (const std::size_t t : terms) {
    x.middleCols(c, termColumns[t].cols()) = termColumns[t];
    c += termColumns[t].cols();
  }
  return x;
}

// Residual sums of squares and cross products of Z after least-squares projection on X.
Eigen::MatrixXd residualSscp(const Eigen::MatrixXd& x, const Eigen::MatrixXd& z) {
  if (x.cols() == 0) return z.transpose() * z;
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(x);
  if (qr.rank() < x.cols())
    throw AnalysisError("the between-subject model is rank deficient (an empty or collinear cell)");
  const Eigen::MatrixXd residual = z - x * qr.solve(z);
  return residual.transpose() * residual;
}

std::string termName(const AnovaDesign& design, Mask between, Mask within) {
  std::string name;
  for (std::size_t f = 0; f < design.between.size(); ++f)
    if (between & (Mask{1} << f)) name += (name.empty() ? "" : ":") + design.between[f].name;
  for (std::size_t f = 0; f < design.within.size(); ++f)
    if (within & (Mask{1} << f)) name += (name.empty() ? "" : ":") + design.within[f].name;
  return name;
}

std::string errorStratumName(const AnovaDesign& design, Mask within) {
  std::string name = "subjects";
  for (std::size_t f = 0; f < design.within.size(); ++f)
    if (within & (Mask{1} << f)) name += " × " + design.within[f].name;
  return name;
}

std::string formatNumber(double x) {
  std::ostringstream out;
  out.precision(6);
  out << x;
  return out.str();
}

}  // namespace

SumOfSquaresType parseSumOfSquaresType(std::string_view text) {
  if (text == "2" || text == "II") return SumOfSquaresType::II;
  if (text == "3" || text == "III") return SumOfSquaresType::III;
  throw AnalysisError("unknown sum-of-squares type '" + std::string(text) + "' (expected 2 or 3)");
}

std::string_view sumOfSquaresTypeName(SumOfSquaresType type) {
  return type == SumOfSquaresType::II ? "II" : "III";
}

namespace {

void checkFactorCounts(const AnovaDesign& design) {
  if (design.between.size() + design.within.size() == 0)
    throw AnalysisError("an ANOVA needs at least one factor");
  if (design.between.size() > 8 || design.within.size() > 8)
    throw AnalysisError("at most 8 between and 8 within factors are supported");
}

// Centre on the grand mean: removes large offsets before any product is formed. Only the
// intercept of the between stratum (the grand mean itself, never reported) is affected.
Eigen::MatrixXd centredResponses(const AnovaDesign& design, double& totalSs) {
  const std::vector<double> all(design.y.data(), design.y.data() + design.y.size());
  const Eigen::MatrixXd y = design.y.array() - rMean(all);
  totalSs = y.squaredNorm();
  if (!(totalSs > 0.0))
    throw AnalysisError("zero variance: all values of '" + design.dv +
                        "' are equal, so every F ratio would be 0/0");
  return y;
}

// The between-subject linear model: every between term's columns and the full model of them all.
struct BetweenModel {
  std::vector<Mask> terms;
  std::vector<Eigen::MatrixXd> termColumns;
  std::vector<std::size_t> allIndices;
  Eigen::MatrixXd fullModel;
  double dfError = 0.0;
  Eigen::Index n = 0;
};

BetweenModel betweenModel(const AnovaDesign& design) {
  BetweenModel model;
  model.n = static_cast<Eigen::Index>(design.subjects.size());
  model.terms = allTerms(design.between.size());
  for (const Mask b : model.terms) model.termColumns.push_back(betweenTermColumns(design, b));
  model.allIndices.resize(model.terms.size());
  for (std::size_t i = 0; i < model.allIndices.size(); ++i) model.allIndices[i] = i;
  model.fullModel = modelMatrix(model.termColumns, model.allIndices, model.n);
  model.dfError = static_cast<double>(model.n - model.fullModel.cols());
  if (model.dfError < 1.0)
    throw AnalysisError("no error degrees of freedom: " + std::to_string(model.n) + " subjects in " +
                        std::to_string(model.fullModel.cols()) + " between-subject cells");
  return model;
}

// One within term's stratum: the transformed responses Z and its error SSCP.
struct Stratum {
  Mask within = 0;
  Eigen::MatrixXd z;
  Eigen::MatrixXd errorSscp;
  double ssError = 0.0;
  std::optional<SphericityResult> sphericity;
};

Stratum withinStratum(const AnovaDesign& design, const BetweenModel& model, const Eigen::MatrixXd& y,
                      const std::vector<std::size_t>& levelCounts, Mask w) {
  Stratum stratum;
  stratum.within = w;
  std::vector<bool> inTerm(design.within.size());
  for (std::size_t f = 0; f < inTerm.size(); ++f) inTerm[f] = (w >> f) & 1u;
  stratum.z = y * withinTermTransform(levelCounts, inTerm);
  stratum.errorSscp = residualSscp(model.fullModel, stratum.z);
  stratum.ssError = stratum.errorSscp.trace();
  if (stratum.z.cols() > 1)
    stratum.sphericity =
        sphericity(stratum.errorSscp, model.dfError, static_cast<double>(design.cellCount()));
  return stratum;
}

// Hypothesis SSCP of between term bi in a stratum: E(reduced) - E(full), the reduced model by
// the type of sums of squares.
Eigen::MatrixXd hypothesisSscp(const BetweenModel& model, const Stratum& stratum, std::size_t bi,
                               SumOfSquaresType ssType) {
  const Mask b = model.terms[bi];
  std::vector<std::size_t> reduced;
  std::vector<std::size_t> full;
  for (std::size_t s = 0; s < model.terms.size(); ++s) {
    const bool keep = ssType == SumOfSquaresType::III ? s != bi : !isSubset(b, model.terms[s]);
    if (keep) reduced.push_back(s);
  }
  full = reduced;
  full.push_back(bi);
  std::sort(full.begin(), full.end());
  const Eigen::MatrixXd eReduced = residualSscp(modelMatrix(model.termColumns, reduced, model.n), stratum.z);
  const Eigen::MatrixXd eFull = full.size() == model.allIndices.size()
                                    ? stratum.errorSscp
                                    : residualSscp(modelMatrix(model.termColumns, full, model.n), stratum.z);
  return eReduced - eFull;
}

// The effect b × T from its hypothesis SSCP: SS, df, F, p (ε-corrected where there is a
// sphericity test) and partial η²; the generalized η² waits for every stratum's error.
AnovaEffect stratumEffect(const AnovaDesign& design, const BetweenModel& model, const Stratum& stratum,
                          std::size_t bi, const Eigen::MatrixXd& h, double totalSs) {
  const Mask b = model.terms[bi];
  const Mask w = stratum.within;
  const double q = static_cast<double>(stratum.z.cols());
  const double ssError = stratum.ssError;
  AnovaEffect e;
  e.name = termName(design, b, w);
  e.withinSubjects = w != 0;
  e.ss = std::max(0.0, h.trace());
  e.ssError = ssError;
  const double dfEffect = static_cast<double>(model.termColumns[bi].cols());
  e.df1 = q * dfEffect;
  e.df2 = q * model.dfError;
  if (!(ssError > totalSs * 1e-13))
    throw AnalysisError("zero error variance for effect '" + e.name + "' (error stratum " +
                        errorStratumName(design, w) + ", SS_error = " + formatNumber(ssError) +
                        "): F would be " +
                        (e.ss > totalSs * 1e-13 ? "infinite" : "0/0, undefined"));
  e.F = (e.ss / e.df1) / (ssError / e.df2);
  e.p = fisherFUpperTail(e.F, e.df1, e.df2);
  if (const auto& sph = stratum.sphericity) {
    e.sphericity = sph;
    e.pGG = fisherFUpperTail(e.F, e.df1 * sph->epsilonGG, e.df2 * sph->epsilonGG);
    const double hf = std::min(1.0, sph->epsilonHF);
    e.pHF = fisherFUpperTail(e.F, e.df1 * hf, e.df2 * hf);
  }
  e.eta2Partial = e.ss / (e.ss + ssError);
  return e;
}

// Effects are listed by order (main effects, then interactions), within terms in stratum order.
struct Pending {
  AnovaEffect effect;
  std::tuple<int, std::size_t, std::size_t> order;  // (number of factors, within term, between term)
};

}  // namespace

AnovaResult anova(const AnovaDesign& design, SumOfSquaresType ssType) {
  checkFactorCounts(design);
  AnovaResult result;
  result.ssType = ssType;
  result.subjects = design.subjects.size();
  result.maxReplicates = design.maxReplicates;

  double totalSs = 0.0;
  const Eigen::MatrixXd y = centredResponses(design, totalSs);
  const BetweenModel model = betweenModel(design);
  const std::vector<Mask> withinTerms = allTerms(design.within.size());
  std::vector<std::size_t> levelCounts;
  for (const auto& f : design.within) levelCounts.push_back(f.levels.size());

  std::vector<Pending> pending;
  std::vector<double> stratumError(withinTerms.size(), 0.0);
  for (std::size_t wi = 0; wi < withinTerms.size(); ++wi) {
    const Mask w = withinTerms[wi];
    const Stratum stratum = withinStratum(design, model, y, levelCounts, w);
    stratumError[wi] = stratum.ssError;
    for (std::size_t bi = 0; bi < model.terms.size(); ++bi) {
      const Mask b = model.terms[bi];
      if (b == 0 && w == 0) continue;  // the grand mean
      const Eigen::MatrixXd h = hypothesisSscp(model, stratum, bi, ssType);
      pending.push_back({stratumEffect(design, model, stratum, bi, h, totalSs),
                         {std::popcount(b) + std::popcount(w), wi, bi}});
    }
  }
  double allErrors = 0.0;
  for (const double s : stratumError) allErrors += s;
  std::stable_sort(pending.begin(), pending.end(),
                   [](const Pending& a, const Pending& b) { return a.order < b.order; });
  for (auto& p : pending) {
    p.effect.eta2Generalized = p.effect.ss / (p.effect.ss + allErrors);
    result.effects.push_back(std::move(p.effect));
  }
  return result;
}

}  // namespace tlab::analysis
