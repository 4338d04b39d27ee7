#include "stimuli/fields/field_registry.hpp"

#include <stdexcept>

#include "stimuli/fields/abc_flow.hpp"
#include "stimuli/fields/double_gyre.hpp"
#include "stimuli/fields/hills_spherical_vortex.hpp"
#include "stimuli/fields/linear_saddle.hpp"
#include "stimuli/fields/solid_rotation.hpp"
#include "stimuli/fields/stiff_relaxation_field.hpp"
#include "stimuli/fields/swirling_jet.hpp"
#include "stimuli/fields/vortex_ring.hpp"

namespace tlab::stimuli {

std::vector<std::string> vectorFieldNames() {
  return {"vortex-ring", "swirling-jet", "abc", "hills-vortex", "double-gyre", "stiff-relaxation", "solid-rotation",
          "linear-saddle"};
}

std::unique_ptr<VectorField> makeVectorField(const std::string& name) {
  if (name == "vortex-ring") return std::make_unique<VortexRing>();
  if (name == "swirling-jet") return std::make_unique<SwirlingJet>();
  if (name == "abc") return std::make_unique<AbcFlow>();
  if (name == "hills-vortex") return std::make_unique<HillsSphericalVortex>();
  if (name == "double-gyre") return std::make_unique<DoubleGyre>();
  if (name == "stiff-relaxation") return std::make_unique<StiffRelaxationField>();
  if (name == "solid-rotation") return std::make_unique<SolidRotation>();
  if (name == "linear-saddle") return std::make_unique<LinearSaddle>();
  std::string known;
  for (const auto& n : vectorFieldNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown vector field '" + name + "' (known: " + known + ")");
}

}  // namespace tlab::stimuli
