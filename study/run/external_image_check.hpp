#pragma once
// The design-time check of images from another renderer (Level::images): every image a design can
// show exists, has the stimulus' size, and covers what tlab's own rendering of the same scene,
// camera and size covers (IoU >= 0.98), else one line naming the image, the IoU and the likely
// cause. Needs a current GL context.
#include <string>
#include <vector>

#include "renderer/scene/builtin_scenes.hpp"
#include "study/design/experiment.hpp"

namespace tlab::study {

struct ImageAlignment {
  std::string image;  // absolute path
  std::string scene;
  std::string sha256;  // of the PNG file
  double iou = 0.0;
};

// One entry per distinct image, in the order the design first shows them; throws
// std::runtime_error "EXPERIMENT: images IMAGE: IoU ... (below 0.98) ...; likely cause: ...".
std::vector<ImageAlignment> checkExternalImages(const Experiment& e, const std::vector<render::BuiltinSceneSpec>& catalog);

}  // namespace tlab::study
