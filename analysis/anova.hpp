#pragma once
// Analysis of variance for between-subject, repeated-measures (within-subject) and mixed designs,
// all computed by one method: the multivariate approach to repeated measures (O'Brien & Kaiser
// 1985, Psych. Bull. 97(2); Maxwell & Delaney 2004, Chs. 11-14), which for the univariate,
// sphericity-assumed tests gives exactly the classical error-strata ANOVA of R's
// aov(y ~ B*W + Error(subject/W)) for balanced data.
//
// For every within term T (a subset of the within factors, including the empty one, which is the
// between-subject stratum) the subject × cell matrix Y is transformed by the orthonormal contrasts
// of T: Z_T = Y C_T (N × q_T). Z_T is then fitted by the between-subject linear model (intercept +
// all between terms, sum-to-zero coding). For a between term b (or the intercept) the hypothesis
// SSCP is H = E(reduced) - E(full) and the error SSCP is E_T = E(all between terms), where E(·) is
// the residual SSCP of a model. The effect b × T then has
//   SS = tr H,  SS_error = tr E_T,  df1 = q_T·df_b,  df2 = q_T·(N - rank X),
//   F = (SS/df1) / (SS_error/df2).
// Within effects with q_T > 1 get Mauchly's test and ε-corrected p-values (see sphericity.hpp).
//
// Types of sums of squares for unbalanced between-subject cells (they coincide when the cells are
// balanced; Maxwell & Delaney 2004 Ch. 7; Langsrud 2003, Stat. Comput. 13):
//  - Type II (default, R car::Anova default): a term is adjusted for every term that does not
//    contain it — reduced model = all terms not containing b, full = reduced + b. For a within
//    main effect (b = intercept) this is the weighted grand mean, as in R's aov.
//  - Type III (SPSS, SAS default): reduced model = all terms except b, sum-to-zero coding, i.e.
//    tests of unweighted marginal means.
// Effect sizes (Olejnik & Algina 2003, Psych. Methods 8(4); Bakeman 2005, Behav. Res. Methods
// 37(3)), every factor treated as manipulated:
//   η²_partial = SS / (SS + SS_error of the effect's stratum),
//   η²_generalized = SS / (SS + Σ over all strata of SS_error).
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/anova_design.hpp"
#include "analysis/sphericity.hpp"

namespace tlab::analysis {

enum class SumOfSquaresType { II, III };
SumOfSquaresType parseSumOfSquaresType(std::string_view text);  // "2"/"II"/"3"/"III"
std::string_view sumOfSquaresTypeName(SumOfSquaresType type);   // "II", "III"

struct AnovaEffect {
  std::string name;             // "group", "time", "group:time"
  bool withinSubjects = false;  // true if the effect involves a within factor
  double ss = 0.0;
  double ssError = 0.0;
  double df1 = 0.0;
  double df2 = 0.0;
  double F = 0.0;
  double p = 1.0;
  std::optional<SphericityResult> sphericity;  // within effects with more than one contrast
  double pGG = std::nan("");  // p with df·ε̂_GG
  double pHF = std::nan("");  // p with df·min(1, ε̃_HF), as R's anova.mlm
  double eta2Partial = 0.0;
  double eta2Generalized = 0.0;
};

struct AnovaResult {
  SumOfSquaresType ssType = SumOfSquaresType::II;
  std::size_t subjects = 0;
  std::size_t maxReplicates = 1;  // > 1: cells of a subject were averaged first
  std::vector<AnovaEffect> effects;
};

// Throws AnalysisError when the error degrees of freedom are zero or an error stratum has zero
// variance (the F ratio would be infinite).
AnovaResult anova(const AnovaDesign& design, SumOfSquaresType ssType = SumOfSquaresType::II);

}  // namespace tlab::analysis
