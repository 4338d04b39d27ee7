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

AnovaResult anova(const AnovaDesign& design, SumOfSquaresType ssType) {
  if (design.between.size() + design.within.size() == 0)
    throw AnalysisError("an ANOVA needs at least one factor");
  if (design.between.size() > 8 || design.within.size() > 8)
    throw AnalysisError("at most 8 between and 8 within factors are supported");
  const auto n = static_cast<Eigen::Index>(design.subjects.size());
  AnovaResult result;
  result.ssType = ssType;
  result.subjects = design.subjects.size();
  result.maxReplicates = design.maxReplicates;

  // Centre on the grand mean: removes large offsets before any product is formed. Only the
  // intercept of the between stratum (the grand mean itself, never reported) is affected.
  const std::vector<double> all(design.y.data(), design.y.data() + design.y.size());
  const Eigen::MatrixXd y = design.y.array() - rMean(all);
  const double totalSs = y.squaredNorm();
  if (!(totalSs > 0.0))
    throw AnalysisError("zero variance: all values of '" + design.dv +
                        "' are equal, so every F ratio would be 0/0");

  const std::vector<Mask> betweenTerms = allTerms(design.between.size());
  const std::vector<Mask> withinTerms = allTerms(design.within.size());
  std::vector<Eigen::MatrixXd> termColumns;
  for (const Mask b : betweenTerms) termColumns.push_back(betweenTermColumns(design, b));
  std::vector<std::size_t> allIndices(betweenTerms.size());
  for (std::size_t i = 0; i < allIndices.size(); ++i) allIndices[i] = i;
  const Eigen::MatrixXd fullModel = modelMatrix(termColumns, allIndices, n);
  const double dfError = static_cast<double>(n - fullModel.cols());
  if (dfError < 1.0)
    throw AnalysisError("no error degrees of freedom: " + std::to_string(n) + " subjects in " +
                        std::to_string(fullModel.cols()) + " between-subject cells");

  std::vector<std::size_t> levelCounts;
  for (const auto& f : design.within) levelCounts.push_back(f.levels.size());

  // Effects are listed by order (main effects, then interactions), within terms in stratum order.
  struct Pending {
    AnovaEffect effect;
    std::tuple<int, std::size_t, std::size_t> order;  // (number of factors, within term, between term)
  };
  std::vector<Pending> pending;
  std::vector<double> stratumError(withinTerms.size(), 0.0);

  for (std::size_t wi = 0; wi < withinTerms.size(); ++wi) {
    const Mask w = withinTerms[wi];
    std::vector<bool> inTerm(design.within.size());
    for (std::size_t f = 0; f < inTerm.size(); ++f) inTerm[f] = (w >> f) & 1u;
    const Eigen::MatrixXd z = y * withinTermTransform(levelCounts, inTerm);
    const double q = static_cast<double>(z.cols());
    const Eigen::MatrixXd errorSscp = residualSscp(fullModel, z);
    const double ssError = errorSscp.trace();
    stratumError[wi] = ssError;
    std::optional<SphericityResult> sph;
    if (z.cols() > 1) sph = sphericity(errorSscp, dfError, static_cast<double>(design.cellCount()));

    for (std::size_t bi = 0; bi < betweenTerms.size(); ++bi) {
      const Mask b = betweenTerms[bi];
      if (b == 0 && w == 0) continue;  // the grand mean
      std::vector<std::size_t> reduced;
      std::vector<std::size_t> full;
      for (std::size_t s = 0; s < betweenTerms.size(); ++s) {
        const bool keep = ssType == SumOfSquaresType::III ? s != bi : !isSubset(b, betweenTerms[s]);
        if (keep) reduced.push_back(s);
      }
      full = reduced;
      full.push_back(bi);
      std::sort(full.begin(), full.end());
      const Eigen::MatrixXd eReduced = residualSscp(modelMatrix(termColumns, reduced, n), z);
      const Eigen::MatrixXd eFull =
          full.size() == allIndices.size() ? errorSscp : residualSscp(modelMatrix(termColumns, full, n), z);
      const Eigen::MatrixXd h = eReduced - eFull;

      AnovaEffect e;
      e.name = termName(design, b, w);
      e.withinSubjects = w != 0;
      e.ss = std::max(0.0, h.trace());
      e.ssError = ssError;
      const double dfEffect = static_cast<double>(termColumns[bi].cols());
      e.df1 = q * dfEffect;
      e.df2 = q * dfError;
      if (!(ssError > totalSs * 1e-13))
        throw AnalysisError("zero error variance for effect '" + e.name + "' (error stratum " +
                            errorStratumName(design, w) + ", SS_error = " + formatNumber(ssError) +
                            "): F would be " +
                            (e.ss > totalSs * 1e-13 ? "infinite" : "0/0, undefined"));
      e.F = (e.ss / e.df1) / (ssError / e.df2);
      e.p = fisherFUpperTail(e.F, e.df1, e.df2);
      if (sph) {
        e.sphericity = sph;
        e.pGG = fisherFUpperTail(e.F, e.df1 * sph->epsilonGG, e.df2 * sph->epsilonGG);
        const double hf = std::min(1.0, sph->epsilonHF);
        e.pHF = fisherFUpperTail(e.F, e.df1 * hf, e.df2 * hf);
      }
      e.eta2Partial = e.ss / (e.ss + ssError);
      pending.push_back({e, {std::popcount(b) + std::popcount(w), wi, bi}});
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
