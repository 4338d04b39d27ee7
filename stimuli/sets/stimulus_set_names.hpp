#pragma once
// The names of a stimulus set's entries: a scene's short name (in image file names), and the
// names {scene} and {view} stand for in the path of images from another renderer.
#include <string>

#include "stimuli/sets/stimulus_set_spec.hpp"

namespace tlab::stimuli {

// "pretzel" from "builtin:pretzel?seed=2", the file stem for glTF files; safe for file names.
std::string shortName(const std::string& source);
// The scene's `name`, else its short name.
std::string sceneName(const SceneEntry& scene);
// The view's `name`, else "v1", "v2", ... (1-based, as in the images' file names).
std::string viewName(const SceneEntry& scene, std::size_t view);
// An images path with {scene} and {view} replaced by those names.
std::string imagesPathFor(const std::string& pattern, const SceneEntry& scene, std::size_t view);

}  // namespace tlab::stimuli
