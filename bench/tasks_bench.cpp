// How long the tasks' exact ground truth takes per question on the biggest built-in meshes
// (issue 11: a full study's questions must be generated in seconds). Each benchmark runs
// probe() for a batch of questions, scene loading excluded; the "per_question" counter is the
// time per question including the one-off structures (AABB tree, welded meshes, Surface_mesh).
#include <benchmark/benchmark.h>

#include <string>

#include "renderer/scene/scene_source.hpp"
#include "tasks/nearest_point/geodesic_distances.hpp"
#include "tasks/task_registry.hpp"
#include "tasks/welded_mesh.hpp"

namespace {

using namespace tlab;

void probeQuestions(benchmark::State& state, const std::string& source, const std::string& taskName,
                    std::vector<std::string> settings, int questionCount) {
  const render::Scene scene = render::loadScene(source);
  const render::Camera camera = scene.camera ? *scene.camera : render::fitCamera(scene.boundingSphere(), 1.0f);
  const auto task = tasks::makeTask(taskName);
  const auto resolved = task->settings(settings);
  std::uint64_t seed = 1;
  for (auto _ : state) {
    auto questions = task->probe({scene, camera, 1024, 1024, questionCount, seed++, resolved});
    benchmark::DoNotOptimize(questions);
  }
  state.counters["triangles"] = double(scene.triangleCount());
  state.counters["per_question"] =
      benchmark::Counter(double(questionCount) * double(state.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// One exact single-source geodesic query (one sequence tree) on a whole welded mesh.
void geodesicFromOneSource(benchmark::State& state, const std::string& source) {
  const render::Scene scene = render::loadScene(source);
  const tasks::WeldedMesh mesh = tasks::weldMesh(scene.objects.at(0).mesh);
  const tasks::GeodesicDistances geodesics(mesh);
  std::vector<tasks::SurfacePoint> targets;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); t += std::uint32_t(mesh.triangles.size() / 32)) targets.push_back({t, glm::dvec3(1.0 / 3.0)});
  std::uint32_t s = 0;
  for (auto _ : state) {
    auto d = geodesics.fromSource({s, glm::dvec3(1.0 / 3.0)}, targets);
    benchmark::DoNotOptimize(d);
    s = (s + 7919) % std::uint32_t(mesh.triangles.size());
  }
  state.counters["triangles"] = double(mesh.triangles.size());
}

const int registered = [] {
  const std::vector<std::string> scenes = {"builtin:torus", "builtin:nested-spheres?n=3", "builtin:open-cylinders",
                                           "builtin:torus?triangles=100000"};
  for (const auto& scene : scenes) {
    benchmark::RegisterBenchmark(("layer-index/" + scene).c_str(), probeQuestions, scene, "layer-index", std::vector<std::string>{}, 10)
        ->Unit(benchmark::kMillisecond);
    if (scene == "builtin:open-cylinders")
      benchmark::RegisterBenchmark(("follow-boundary/" + scene).c_str(), probeQuestions, scene, "follow-boundary",
                                   std::vector<std::string>{}, 10)
          ->Unit(benchmark::kMillisecond);
    if (scene != "builtin:nested-spheres?n=3")  // concentric spheres admit no Euclidean trap
      benchmark::RegisterBenchmark(("nearest-point/" + scene).c_str(), probeQuestions, scene, "nearest-point",
                                   std::vector<std::string>{}, scene.find("100000") == std::string::npos ? 10 : 2)
          ->Unit(benchmark::kMillisecond)
          ->Iterations(1);
  }
  benchmark::RegisterBenchmark("nearest-point/builtin:nested-spheres?n=3 (no trap)", probeQuestions,
                               std::string("builtin:nested-spheres?n=3"), "nearest-point",
                               std::vector<std::string>{"euclidean-trap-share=0"}, 10)
      ->Unit(benchmark::kMillisecond)
      ->Iterations(1);
  for (const auto& scene : {"builtin:torus", "builtin:torus?triangles=100000"})
    benchmark::RegisterBenchmark((std::string("geodesic-one-source/") + scene).c_str(), geodesicFromOneSource, std::string(scene))
        ->Unit(benchmark::kMillisecond)
        ->Iterations(2);
  return 0;
}();

}  // namespace
