#pragma once
// NelderMead: derivative-free minimisation of a function of a few parameters (Nelder & Mead 1965,
// "A simplex method for function minimization", Computer Journal 7(4) 308-313), with the standard
// coefficients (reflection 1, expansion 2, contraction 1/2, shrink 1/2) as in Lagarias et al. 1998,
// SIAM J. Optim. 9(1) 112-147. Written here because none of the libraries on the build machines
// offers a multivariate derivative-free minimiser for a general objective: Boost 1.74's
// brent_find_minima is one-dimensional, and Eigen's LevenbergMarquardt fits only sums of squares.
// Deterministic: the same start gives the same result.
#include <functional>
#include <vector>

namespace tlab::analysis {

struct NelderMeadOptions {
  std::vector<double> initialStep;  // per parameter; empty: 10 % of |start| (0.1 where start is 0)
  double tolerance = 1e-9;          // stop when the simplex's values differ by less (absolute)
  int maxEvaluations = 4000;
};

struct NelderMeadResult {
  std::vector<double> x;
  double value = 0.0;
  int evaluations = 0;
  bool converged = false;
};

NelderMeadResult nelderMeadMinimize(const std::function<double(const std::vector<double>&)>& f,
                                    std::vector<double> start, const NelderMeadOptions& options = {});

}  // namespace tlab::analysis
