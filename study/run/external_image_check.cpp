#include "study/run/external_image_check.hpp"

#include "core/file_text.hpp"
#include "core/sha256.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "stimuli/sets/external_image_alignment.hpp"
#include "study/design/image_files.hpp"
#include "study/run/stimulus_library.hpp"

namespace tlab::study {

namespace {

ImageAlignment align(const Experiment& e, const StimulusKey& key, const std::vector<render::BuiltinSceneSpec>& catalog) {
  const render::Scene scene = render::loadScene(key.scene, catalog);
  const core::Image image = stimuli::readExternalImage(key.images, key.width, key.height);
  render::Renderer renderer(scene);
  const auto result = stimuli::alignWithView(renderer, stimulusCamera(scene, key), image);
  if (!result.aligned) throw std::runtime_error(e.path + ": images " + stimuli::misalignmentMessage(key.images, key.scene, result));
  const auto bytes = core::readFileText(key.images);
  return {key.images, key.scene, core::sha256Hex(bytes.value_or("")), result.iou};
}

}  // namespace

std::vector<ImageAlignment> checkExternalImages(const Experiment& e, const std::vector<render::BuiltinSceneSpec>& catalog) {
  std::vector<ImageAlignment> out;
  for (const auto& key : externalImageStimuli(e)) out.push_back(align(e, key, catalog));
  return out;
}

}  // namespace tlab::study
