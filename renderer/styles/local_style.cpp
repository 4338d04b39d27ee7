#include "renderer/styles/local_style.hpp"

#include <stdexcept>

#include "renderer/styles/constant_style.hpp"

namespace tlab::render {

IllustrativeSettings localShadingOf(const Style& style, const StyleParams& params) {
  if (const auto* local = dynamic_cast<const LocalStyle*>(&style)) return local->illustrative(params);
  if (dynamic_cast<const ConstantStyle*>(&style))
    return IllustrativeSettings::constant(static_cast<float>(params.number("alpha")), IllustrativeSettings::lightingShading(params));
  throw std::invalid_argument("style '" + style.name() +
                              "' is not local per fragment and cannot be depth-peeled (local styles: constant, angle, "
                              "normal-variation, iris)");
}

}  // namespace tlab::render
