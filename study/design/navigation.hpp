#pragma once
// Navigation: how a participant may move the camera in an interactive trial (an experiment file's
// `navigation = none|orbit|walk`). The motion itself is study/run/camera_navigator.hpp; the design
// floor needs only the name.
#include <string>

namespace tlab::study {

enum class Navigation { None, Orbit, Walk };

// "none", "orbit", "walk"; throws std::invalid_argument naming the value.
Navigation parseNavigation(const std::string& text);
const char* navigationName(Navigation navigation);

}  // namespace tlab::study
