#include "study/design/navigation.hpp"

#include <stdexcept>

namespace tlab::study {

Navigation parseNavigation(const std::string& text) {
  if (text == "none") return Navigation::None;
  if (text == "orbit") return Navigation::Orbit;
  if (text == "walk") return Navigation::Walk;
  throw std::invalid_argument("navigation '" + text + "': expected none, orbit or walk");
}

const char* navigationName(Navigation n) {
  switch (n) {
    case Navigation::None: return "none";
    case Navigation::Orbit: return "orbit";
    case Navigation::Walk: return "walk";
  }
  return "none";
}

}  // namespace tlab::study
