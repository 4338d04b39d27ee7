#pragma once
// The analytic fields by name, for the command line and stimulus-set files.
#include <memory>
#include <string>
#include <vector>

#include "stimuli/fields/vector_field.hpp"

namespace tlab::stimuli {

std::vector<std::string> vectorFieldNames();
// Default parameters; throws std::invalid_argument listing the known names.
std::unique_ptr<VectorField> makeVectorField(const std::string& name);

}  // namespace tlab::stimuli
