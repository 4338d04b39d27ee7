#pragma once
// manifest.json of a stimulus set: the set's parameters and seeds, each scene, and per image its
// style, view camera, probe positions (2-D pixel and 3-D world), question and ground truth (when
// the probe source provides it) and SHA-256 (and, for images from another renderer, the source
// image's path, SHA-256 and alignment IoU), and the GL backend/vendor/renderer/version that drew them. No time stamps or absolute paths: the same inputs
// give the same bytes.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/scene/scene.hpp"
#include "stimuli/sets/stimulus_set_renderer.hpp"

namespace tlab::stimuli {

nlohmann::json cameraJson(const render::Camera& camera);

nlohmann::json stimulusSetManifest(const StimulusSetSpec& spec, const std::vector<render::Scene>& scenes,
                                   const std::vector<RenderedStimulus>& stimuli,
                                   const std::vector<std::pair<std::size_t, std::string>>& floorPlans,
                                   const gpu::GpuInfo& gpu);

}  // namespace tlab::stimuli
