#pragma once
// Sphericity of a within-subject effect: Mauchly's test and the Greenhouse-Geisser and
// Huynh-Feldt corrections, computed from the error SSCP matrix E (q × q) of the effect's
// orthonormal contrasts and its error degrees of freedom n.
#include <Eigen/Dense>

namespace tlab::analysis {

struct SphericityResult {
  double mauchlyW = 1.0;
  double mauchlyChiSquared = 0.0;
  double mauchlyDf = 0.0;
  double mauchlyP = 1.0;    // NaN when n < q (E singular, test undefined)
  double epsilonGG = 1.0;   // Greenhouse & Geisser (1959) / Box (1954) ε̂
  double epsilonHF = 1.0;   // Huynh & Feldt (1976) ε̃, uncapped as R prints it (may exceed 1)
};

// Mauchly (1940): W = det(E) / (tr(E)/q)^q. The χ² approximation with Anderson's (1958, Sec.
// 10.7.4) second-order correction, as in R's mauchly.test / car::Anova:
//   ρ = 1 - (2q² + q + 2)/(6qn),  z = -nρ log W,  f = q(q+1)/2 - 1,
//   ω₂ = (q+2)(q-1)(q-2)(2q³ + 6q² + 3K + 2) / (288 (nqρ)²),
//   p = P(χ²_f > z) + ω₂ (P(χ²_{f+4} > z) - P(χ²_f > z)).
// K is the untransformed dimension (the number of within cells): R's stats:::mauchly.test.SSD
// (which car::Anova calls) writes "3 * p" with p = ncol(SSD) there, where Anderson's formula has
// 3q. We follow R so that results match R and car to full precision; the two agree whenever
// q = 2 (ω₂ = 0) and otherwise differ only in this small second-order term.
// ε̂_GG = (Σλ)² / (q Σλ²) over the eigenvalues λ of E (Box 1954).
// ε̃_HF = ((n+1) q ε̂ - 2) / (q (n - q ε̂)) (R's stats:::sphericity; with one group n + 1 = N and this
// is Huynh & Feldt's N(k-1)ε̂ - 2 over (k-1)(N-1-(k-1)ε̂); with several groups it is Lecoutre's
// 1991 correction).
// Log-space throughout: log W = Σ log λ - q log(Σλ/q), so W never underflows for large q.
SphericityResult sphericity(const Eigen::MatrixXd& errorSscp, double errorDf, double cellCount);

}  // namespace tlab::analysis
