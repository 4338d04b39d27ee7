#include "analysis/bobyqa.hpp"

#include <nlopt.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

namespace {

struct Objective {
  const std::function<double(const Eigen::VectorXd&)>* f;
  int evaluations = 0;
};

double call(unsigned n, const double* x, double* /*gradient*/, void* data) {
  auto* o = static_cast<Objective*>(data);
  ++o->evaluations;
  const double v = (*o->f)(Eigen::Map<const Eigen::VectorXd>(x, static_cast<Eigen::Index>(n)));
  return std::isfinite(v) ? v : std::numeric_limits<double>::max();
}

struct OptDeleter {
  void operator()(nlopt_opt o) const { nlopt_destroy(o); }
};

}  // namespace

BobyqaResult minimizeBobyqa(const std::function<double(const Eigen::VectorXd&)>& f, const Eigen::VectorXd& start,
                            const Eigen::VectorXd& lower, const BobyqaOptions& options) {
  const auto n = static_cast<unsigned>(start.size());
  BobyqaResult r;
  r.x = start;
  Objective objective{&f};
  if (n == 0) {
    r.value = f(start);
    return r;
  }
  std::unique_ptr<nlopt_opt_s, OptDeleter> opt(nlopt_create(NLOPT_LN_BOBYQA, n));
  if (!opt) throw AnalysisError("NLopt could not create a BOBYQA optimiser");
  std::vector<double> lo(lower.data(), lower.data() + n);
  nlopt_set_lower_bounds(opt.get(), lo.data());
  nlopt_set_min_objective(opt.get(), call, &objective);
  nlopt_set_ftol_abs(opt.get(), options.ftolAbs);
  nlopt_set_xtol_abs1(opt.get(), options.xtolAbs);
  nlopt_set_maxeval(opt.get(), options.maxEvaluations);
  if (options.initialStep.size() == start.size()) nlopt_set_initial_step(opt.get(), options.initialStep.data());
  std::vector<double> x(start.data(), start.data() + n);
  double value = 0.0;
  const nlopt_result status = nlopt_optimize(opt.get(), x.data(), &value);
  r.x = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(n));
  r.value = value;
  r.evaluations = objective.evaluations;
  r.converged = status > 0 && status != NLOPT_MAXEVAL_REACHED;
  if (status == NLOPT_MAXEVAL_REACHED) r.message = "the optimiser reached its limit of " + std::to_string(options.maxEvaluations) + " evaluations";
  else if (status < 0) r.message = "the optimiser failed (NLopt status " + std::to_string(static_cast<int>(status)) + ")";
  return r;
}

}  // namespace tlab::analysis
