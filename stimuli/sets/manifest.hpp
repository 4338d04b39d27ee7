#pragma once
// manifest.json of a stimulus set: the set's parameters and seeds, each scene, and per image its
// style, view camera, probe positions (2-D pixel and 3-D world), question and ground truth (when
// the probe source provides it) and SHA-256 (and, for images from another renderer, the source
// image's path, SHA-256 and alignment IoU), the GL backend/vendor/renderer/version that drew them
// and the tlab version with its git revision. No time stamps or absolute paths: the same inputs
// and the same tlab give the same bytes.
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
                                   const gpu::GpuInfo& gpu, const std::string& tlabVersion);

}  // namespace tlab::stimuli
