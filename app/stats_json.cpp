#include "app/stats_json.hpp"

#include "app/build_revision.hpp"
#include "app/gl_option.hpp"

namespace tlab::app {

nlohmann::json cameraToJson(const render::Camera& c, int width, int height) {
  const auto v = [](glm::vec3 p) { return nlohmann::json::array({p.x, p.y, p.z}); };
  return {{"eye", v(c.eye)}, {"target", v(c.target)}, {"up", v(c.up)}, {"fovy", c.fovyDegrees},
          {"near", c.nearPlane}, {"far", c.farPlane}, {"width", width}, {"height", height}};
}

nlohmann::json statsToJson(const render::RenderStats& s, const gpu::GpuInfo& gpu) {
  nlohmann::json passes = nlohmann::json::object(), order = nlohmann::json::array();
  for (const auto& [name, ms] : s.passMilliseconds) {
    passes[name] = ms;
    order.push_back(name);
  }
  return {{"fragments", s.fragments},
          {"max_list_length", s.maxListLength},
          {"mean_list_length", s.meanListLength},
          {"mean_covered_list_length", s.meanCoveredListLength},
          {"rerenders", s.rerenders},
          {"pool_growths", s.poolGrowths},
          {"pool_capacity", s.poolCapacity},
          {"fill", s.fillMethod},
          {"fragment_properties", s.fragmentProperties},
          {"triangles", s.triangles},
          {"pass_ms", passes},
          {"passes_run", order},
          {"operations", s.operations},
          {"camera", cameraToJson(s.camera, s.width, s.height)},
          {"gpu", gpuInfoToJson(gpu)},
          {"tlab_version", versionString()}};
}

}  // namespace tlab::app
