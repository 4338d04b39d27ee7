#include "study/run/external_image_check.hpp"

#include <set>
#include <sstream>

#include "core/file_text.hpp"
#include "core/sha256.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "stimuli/sets/external_image_alignment.hpp"
#include "study/design/counterbalancing.hpp"
#include "study/design/session_plan.hpp"
#include "study/run/stimulus_library.hpp"

namespace tlab::study {

namespace {

// The stimuli with images, once each, over every participant slot of one balanced round.
std::vector<StimulusKey> imageStimuli(const Experiment& e) {
  const Design design = makeDesign(e);
  std::vector<StimulusKey> keys;
  std::set<std::string> seen;
  for (std::size_t slot = 0; slot < design.balancedMultiple(); ++slot)
    for (const auto& t : makeSessionPlan(e, design, int(slot)).trials)
      if (!t.stimulus.images.empty() && seen.insert(t.stimulus.images).second) keys.push_back(t.stimulus);
  return keys;
}

ImageAlignment align(const Experiment& e, const StimulusKey& key, const std::vector<render::BuiltinSceneSpec>& catalog) {
  const render::Scene scene = render::loadScene(key.scene, catalog);
  render::RenderRequest request;  // tlab's coverage: the pixels with at least one fragment
  request.width = key.width;
  request.height = key.height;
  request.style = "constant";
  request.camera = stimulusCamera(scene, key);
  request.timePasses = false;
  render::Renderer renderer(scene);
  renderer.render(request);
  const auto ours = stimuli::coverageFromCounts(renderer.layerCounts(), key.width, key.height);
  const auto theirs = stimuli::imageCoverage(readExternalImage(key));
  const auto result = stimuli::compareCoverage(ours, theirs);
  std::ostringstream iou;
  iou.precision(4);
  iou << result.iou;
  if (!result.aligned)
    throw std::runtime_error(e.path + ": images " + key.images + ": IoU " + iou.str() + " with tlab's coverage of " + key.scene +
                             " (below 0.98): the image does not show tlab's view; likely cause: " + result.likelyCause);
  const auto bytes = core::readFileText(key.images);
  return {key.images, key.scene, core::sha256Hex(bytes.value_or("")), result.iou};
}

}  // namespace

std::vector<ImageAlignment> checkExternalImages(const Experiment& e, const std::vector<render::BuiltinSceneSpec>& catalog) {
  std::vector<ImageAlignment> out;
  for (const auto& key : imageStimuli(e)) out.push_back(align(e, key, catalog));
  return out;
}

}  // namespace tlab::study
