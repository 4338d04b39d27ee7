#pragma once
// Every built-in scene a study can name: the renderer's own, the stimuli library's (flow surfaces,
// Elmqvist's worlds), the technical scenes, and the T2 letter-pattern world, whose 5x7 bitmaps
// come from the tasks library. study/ is the floor that sees both stimuli/ and tasks/.
#include <vector>

#include "renderer/scene/builtin_scenes.hpp"

namespace tlab::study {

const std::vector<render::BuiltinSceneSpec>& sceneCatalog();

}  // namespace tlab::study
