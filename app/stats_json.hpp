#pragma once
#include <nlohmann/json.hpp>

#include "renderer/gpu/gpu_context.hpp"
#include "renderer/pipeline/renderer.hpp"

namespace tlab::app {

nlohmann::json cameraToJson(const render::Camera& c, int width, int height);
nlohmann::json statsToJson(const render::RenderStats& s, const gpu::GpuInfo& gpu);

}  // namespace tlab::app
