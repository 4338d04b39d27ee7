#include "stimuli/sets/manifest.hpp"

#include "stimuli/sets/booklet_code.hpp"

#include <filesystem>

namespace tlab::stimuli {

namespace {

nlohmann::json vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }
nlohmann::json vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }
nlohmann::json vec(const glm::dvec2& v) { return {v.x, v.y}; }

nlohmann::json sceneJson(const SceneEntry& entry, const render::Scene& scene, std::size_t index) {
  std::size_t targets = 0;
  for (const auto& o : scene.objects) targets += render::hasRole(o.roles, render::Role::Target) ? 1 : 0;
  return {{"index", index + 1},
          {"source", entry.source},
          {"name", scene.name},
          {"objects", scene.objects.size()},
          {"targets", targets},
          {"triangles", scene.triangleCount()},
          {"views", entry.views.size()}};
}

nlohmann::json probesJson(const ProbeQuestion& q) {
  nlohmann::json marks = nlohmann::json::array();
  for (const auto& m : q.marks) marks.push_back({{"label", m.label}, {"role", m.role}, {"world", vec(m.world)}, {"pixel", vec(m.pixel)}});
  return marks;
}

}  // namespace

nlohmann::json cameraJson(const render::Camera& c) {
  return {{"eye", vec(c.eye)}, {"target", vec(c.target)}, {"up", vec(c.up)}, {"fovy", c.fovyDegrees}, {"near", c.nearPlane}, {"far", c.farPlane}};
}

nlohmann::json stimulusSetManifest(const StimulusSetSpec& spec, const std::vector<render::Scene>& scenes,
                                   const std::vector<RenderedStimulus>& stimuli,
                                   const std::vector<std::pair<std::size_t, std::string>>& floorPlans,
                                   const gpu::GpuInfo& gpu, const std::string& tlabVersion) {
  nlohmann::json styles = nlohmann::json::array();
  for (std::size_t i = 0; i < spec.styles.size(); ++i) {
    styles.push_back({{"index", i + 1}, {"name", spec.styles[i].name}, {"settings", spec.styles[i].settings}});
    if (!spec.styles[i].fileSha256.empty()) styles.back()["style_sha256"] = spec.styles[i].fileSha256;
    if (!spec.styles[i].images.empty()) styles.back()["images"] = spec.styles[i].images;
  }
  nlohmann::json sceneList = nlohmann::json::array();
  for (std::size_t i = 0; i < spec.scenes.size(); ++i) {
    nlohmann::json s = sceneJson(spec.scenes[i], scenes[i], i);
    for (const auto& [scene, path] : floorPlans)
      if (scene == i) s["floor_plan"] = path;
    nlohmann::json probeSets = nlohmann::json::array();
    for (const auto& p : spec.scenes[i].probeSets)
      probeSets.push_back({{"task", p.spec.task}, {"count", p.spec.count}, {"seed", p.spec.seed}, {"settings", p.spec.settings}});
    s["probe_sets"] = probeSets;
    sceneList.push_back(s);
  }
  nlohmann::json list = nlohmann::json::array();
  for (const auto& s : stimuli) {
    const ViewEntry& view = spec.scenes[s.scene].views[s.view];
    nlohmann::json item = {{"id", s.id},
                           {"image", s.image},
                           {"sha256", s.sha256},
                           {"booklet_code", bookletCode(s.sha256)},
                           {"scene", s.scene + 1},
                           {"style", s.style + 1},
                           {"view", {{"index", s.view + 1}, {"azimuth", view.azimuthDegrees}, {"elevation", view.elevationDegrees},
                                     {"camera_text", view.camera}, {"camera", cameraJson(s.camera)}}}};
    if (!s.source.path.empty())  // the raw image from another renderer, before the marks
      item["source_image"] = {{"path", s.source.path}, {"sha256", s.source.sha256}, {"iou", s.source.iou}};
    if (s.probeSet >= 0) {
      item["probe_set"] = s.probeSet + 1;
      item["question"] = {{"number", s.question + 1},
                          {"text", s.probes.text},
                          {"answer_format", s.probes.answerFormat},
                          {"probes", probesJson(s.probes)},
                          {"ground_truth", s.probes.groundTruth}};
    }
    list.push_back(item);
  }
  return {{"generator", "tlab stimuli"},
          {"tlab_version", tlabVersion},
          {"set", {{"name", spec.name},
                   {"file", std::filesystem::path(spec.file).filename().string()},
                   {"size", {spec.width, spec.height}},
                   {"seed", spec.seed},
                   {"booklet", spec.booklet}}},
          {"gl", {{"backend", gpu.backend}, {"vendor", gpu.vendor}, {"renderer", gpu.renderer}, {"version", gpu.version}}},
          {"styles", styles},
          {"scenes", sceneList},
          {"stimuli", list}};
}

}  // namespace tlab::stimuli
