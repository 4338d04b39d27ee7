#include "renderer/ops/smart_settings.hpp"

#include <cmath>
#include <stdexcept>

namespace tlab::render {

int substepsFor(double lambda, double bound) {
  return lambda <= bound ? 1 : static_cast<int>(std::ceil(lambda / bound - 1e-12));
}

DiffusionScheme automaticScheme(double lambda, double bound) {
  if (lambda <= bound) return DiffusionScheme::Explicit;
  return substepsFor(lambda, bound) <= kMaxAutoSubsteps ? DiffusionScheme::Substep : DiffusionScheme::Implicit;
}

double SmartSettings::explicitBound() const {
  return normalizedLaplacian ? kExplicitStableLambdaNormalized : kExplicitStableLambdaSum;
}

int SmartSettings::alphaDispatchesPerStep() const {
  if (!diffusesAlpha()) return 0;
  if (scheme == DiffusionScheme::Implicit) return jacobiSweeps;
  if (scheme == DiffusionScheme::Explicit) return 1;
  return substepsFor(lambdaAlpha, explicitBound());
}

SmartSettings SmartSettings::from(const StyleParams& params) {
  SmartSettings s;
  s.iterations = static_cast<int>(std::lround(params.number("iterations")));
  s.lambdaAlpha = params.number("lambda_alpha");
  s.lambdaBeta = params.number("lambda_beta");
  s.lambdaGamma = params.number("lambda_gamma");
  s.s = params.number("s");
  s.adaptiveAlpha = params.is("alpha_init", "adaptive");
  s.modifier = params.is("modifier", "exp") ? 1 : params.is("modifier", "pow") ? 2 : 0;
  s.p = params.number("p");
  s.spreadByMax = params.is("spread", "max");
  s.halos = params.is("halos", "on");
  s.silhouettes = params.is("silhouettes", "on");
  s.wz = params.number("wz");
  s.wn = params.number("wn");
  s.normalizedLaplacian = params.is("laplacian", "normalized");
  const std::string& solver = params.choice("solver");
  s.jacobiSweeps = static_cast<int>(std::lround(params.number("jacobi_sweeps")));
  if (solver == "implicit") s.scheme = DiffusionScheme::Implicit;
  else if (solver == "explicit") s.scheme = DiffusionScheme::Explicit;
  else if (solver == "substep") s.scheme = DiffusionScheme::Substep;
  else s.scheme = automaticScheme(s.lambdaAlpha, s.explicitBound());
  if (s.scheme == DiffusionScheme::Explicit && s.lambdaAlpha > s.explicitBound())
    throw std::invalid_argument(s.normalizedLaplacian
                                    ? "style 'smart': solver=explicit is unstable for lambda_alpha > 1 with laplacian=normalized "
                                      "(Eq. 8 needs lambda <= 1); use solver=auto, substep or implicit"
                                    : "style 'smart': solver=explicit is unstable for lambda_alpha > 0.25 with laplacian=sum (Eq. 8 "
                                      "needs lambda*4 <= 1 on the 4-neighbour graph); use solver=auto, substep or implicit");
  return s;
}

}  // namespace tlab::render
