#include "renderer/ops/smart_settings.hpp"

#include <cmath>
#include <stdexcept>

namespace tlab::render {

int substepsFor(double lambda) {
  return lambda <= kExplicitStableLambda ? 1 : static_cast<int>(std::ceil(lambda / kExplicitStableLambda - 1e-12));
}

DiffusionScheme automaticScheme(double lambda) {
  if (lambda <= kExplicitStableLambda) return DiffusionScheme::Explicit;
  return substepsFor(lambda) <= kMaxAutoSubsteps ? DiffusionScheme::Substep : DiffusionScheme::Implicit;
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
  const std::string& solver = params.choice("solver");
  s.jacobiSweeps = static_cast<int>(std::lround(params.number("jacobi_sweeps")));
  if (solver == "implicit") s.scheme = DiffusionScheme::Implicit;
  else if (solver == "explicit") s.scheme = DiffusionScheme::Explicit;
  else if (solver == "substep") s.scheme = DiffusionScheme::Substep;
  else s.scheme = automaticScheme(s.lambdaAlpha);
  if (s.scheme == DiffusionScheme::Explicit && s.lambdaAlpha > kExplicitStableLambda)
    throw std::invalid_argument("style 'smart': solver=explicit is unstable for lambda_alpha > 0.25 (Eq. 8 needs "
                                "lambda*4 <= 1 on the 4-neighbour graph); use solver=auto, substep or implicit");
  return s;
}

}  // namespace tlab::render
