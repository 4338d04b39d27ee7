#include "study/design/scene_catalog.hpp"

#include "renderer/scene/technical_scenes.hpp"
#include "stimuli/scenes/stimulus_scenes.hpp"
#include "tasks/letter_patterns.hpp"

namespace tlab::study {

const std::vector<render::BuiltinSceneSpec>& sceneCatalog() {
  static const std::vector<render::BuiltinSceneSpec> catalog = [] {
    std::vector<render::BuiltinSceneSpec> extra = render::technicalScenes();
    extra.push_back(stimuli::abstractPatternSpec(tasks::patternLetters(), tasks::letterCells));
    return stimuli::allSceneSpecs(extra);
  }();
  return catalog;
}

}  // namespace tlab::study
