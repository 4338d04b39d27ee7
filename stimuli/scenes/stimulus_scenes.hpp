#pragma once
// The stimuli library's built-in scenes, for `builtin:NAME` next to the renderer's own:
// pretzel, bubble, toroid, abstract, walkthrough (Diepstraten's mug-box, mugs and crank-cylinder
// are the renderer's technicalScenes()); and
// abstract-pattern, whose letter bitmaps are owned by the tasks library: the application passes
// them in (abstractPatternSpec), so stimuli never depends on tasks.
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/builtin_scenes.hpp"

namespace tlab::stimuli {

const std::vector<render::BuiltinSceneSpec>& stimulusScenes();

// Filled (column, row) cells of a letter's 5 × 7 bitmap (e.g. tasks::letterCells).
using LetterCells = std::function<std::vector<glm::ivec2>(char letter)>;

// `builtin:abstract-pattern?letter=I&seed=S`: letter index I into `letters` (e.g. "CKRXY": 1 = K).
render::BuiltinSceneSpec abstractPatternSpec(const std::string& letters, LetterCells cells);

// The renderer's built-ins followed by stimulusScenes() (and `extra`).
std::vector<render::BuiltinSceneSpec> allSceneSpecs(const std::vector<render::BuiltinSceneSpec>& extra = {});

}  // namespace tlab::stimuli
