// tlab task: the study tasks' questions with exact ground truth (probe), scoring one answer
// (check), and the tasks with their settings (list). Question K of `check` is the K-th question
// `probe` prints for the same scene, task, seed, size, camera and settings.
#include <cstdio>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/scene_options.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "tasks/question_json.hpp"
#include "tasks/task_registry.hpp"

namespace tlab::app {

namespace {

struct TaskOptions {
  std::string scene;
  std::string task;
  int count = 1;
  std::uint64_t seed = 1;
  std::string size = "512x512";
  std::string camera;
  std::vector<std::string> settings;
  bool json = false;
  // check only
  int question = 1;
  std::string answer;
  bool missing = false;
  double seconds = -1.0;
};

// The camera a render of the same SCENE, --size and --camera uses (Renderer::resolveCamera).
render::Camera resolveCamera(const render::Scene& scene, const TaskOptions& o, int width, int height) {
  const render::BoundingSphere sphere = scene.boundingSphere();
  const render::Camera base = scene.camera ? *scene.camera : render::fitCamera(sphere, float(width) / float(height));
  if (o.camera.empty()) return base;
  const render::Camera c = render::parseCamera(o.camera, base);
  const bool clipGiven = o.camera.find("near=") != std::string::npos || o.camera.find("far=") != std::string::npos;
  return clipGiven ? c : render::fitClipPlanes(c, sphere);
}

// The questions, and the camera they were probed with (the scene's own or --camera's).
std::vector<tasks::Question> probeQuestions(const TaskOptions& o, int count, const tasks::Task& task, render::Scene& scene,
                                            render::Camera& camera) {
  const auto [width, height] = parseSize(o.size);
  scene = render::loadScene(o.scene, sceneCatalog());
  render::requireTriangles(scene, o.scene);
  camera = resolveCamera(scene, o, width, height);
  const tasks::ProbeRequest request{scene, camera, width, height, count, o.seed, task.settings(o.settings)};
  return task.probe(request);
}

// "camera" is the camera used, in --camera's form (pass it back to reproduce the view exactly).
nlohmann::json header(const TaskOptions& o, const render::Camera& camera) {
  return {{"scene", o.scene}, {"task", o.task}, {"seed", o.seed}, {"size", o.size}, {"camera", render::cameraText(camera)},
          {"settings", o.settings}};
}

void printQuestion(const tasks::Question& q) {
  std::printf("question %d: %s\n", q.number, q.text.c_str());
  for (const auto& p : q.points)
    std::printf("  %-10s %-9s pixel (%8.2f, %8.2f)  world (%9.5f, %9.5f, %9.5f)  object %d\n", p.label.c_str(), p.role.c_str(),
                p.pixel.x, p.pixel.y, p.world.x, p.world.y, p.world.z, p.object);
  std::printf("  truth: %s\n", tasks::groundTruthJson(q.truth).dump().c_str());
  for (const auto& c : q.checks) std::printf("  check: %s = %g (required %g)\n", c.rule.c_str(), c.value, c.required);
}

void runProbe(const TaskOptions& o) {
  const auto task = tasks::makeTask(o.task);
  render::Scene scene;
  render::Camera camera;
  const auto questions = probeQuestions(o, o.count, *task, scene, camera);
  if (o.json) {
    nlohmann::json j = header(o, camera);
    j["questions"] = nlohmann::json::array();
    for (const auto& q : questions) j["questions"].push_back(tasks::toJson(q));
    std::cout << j.dump(2) << "\n";
    return;
  }
  for (const auto& q : questions) printQuestion(q);
}

void runCheck(const TaskOptions& o) {
  const auto task = tasks::makeTask(o.task);
  if (o.question < 1) throw std::invalid_argument("--question: must be >= 1");
  if (o.missing == !o.answer.empty()) throw std::invalid_argument("give exactly one of --answer TEXT and --missing");
  render::Scene scene;
  render::Camera camera;
  const auto questions = probeQuestions(o, o.question, *task, scene, camera);
  const tasks::Question& q = questions.back();
  tasks::Answer answer;
  if (!o.missing) answer.text = o.answer;
  if (o.seconds >= 0.0) answer.seconds = o.seconds;
  const tasks::Score s = task->score(q, answer);
  if (o.json) {
    nlohmann::json j = header(o, camera);
    j["question"] = tasks::toJson(q);
    j["score"] = tasks::toJson(s);
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("question %d: %s\n", q.number, q.text.c_str());
  std::printf("answer '%s': %s (score %g)", s.rawAnswer.c_str(), s.correct ? "correct" : "wrong", s.value);
  if (s.partialCredit) std::printf(", partial credit %g", *s.partialCredit);
  if (s.error) std::printf(", error %g", *s.error);
  if (!s.note.empty()) std::printf(" [%s]", s.note.c_str());
  std::printf("\ntruth: %s\n", tasks::groundTruthJson(q.truth).dump().c_str());
}

void runList() {
  for (const auto& name : tasks::taskNames()) {
    const auto task = tasks::makeTask(name);
    std::printf("%s: %s\n", name.c_str(), task->summary().c_str());
    for (const auto& s : task->settingSpecs())
      std::printf("  --set %s=%s  %s%s\n", s.key.c_str(), s.defaultValue.empty() ? "\"\"" : s.defaultValue.c_str(), s.help.c_str(),
                  s.numeric ? (" (" + s.rangeText() + ")").c_str() : "");
  }
}

void addCommonOptions(CLI::App& cmd, TaskOptions& o) {
  cmd.add_option("scene", o.scene, "a glTF file (.gltf/.glb) or builtin:NAME[?param=value&...]")->required();
  cmd.add_option("--task", o.task, "layer-index, follow-boundary, nearest-point, counting, target-discovery, pattern, gauge-figure or relative-depth")->required();
  cmd.add_option("--seed", o.seed, "random seed of the probe selection")->capture_default_str();
  cmd.add_option("--size", o.size, "image size WxH of the stimulus")->capture_default_str();
  cmd.add_option("--camera", o.camera, "\"eye=X,Y,Z target=X,Y,Z up=X,Y,Z fovy=DEG [near=N far=F]\"");
  cmd.add_option("--set", o.settings, "task setting key=value (repeatable; see `tlab task list`)");
  cmd.add_flag("--json", o.json, "print JSON");
}

}  // namespace

void addTaskCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("task", "Study tasks: questions with exact ground truth, and scoring");
  cmd->require_subcommand(1);

  auto probe = std::make_shared<TaskOptions>();
  auto* p = cmd->add_subcommand("probe", "Choose questions (probe points) and print them with their ground truth");
  addCommonOptions(*p, *probe);
  p->add_option("--count", probe->count, "number of questions")->capture_default_str();
  p->callback([probe] { runProbe(*probe); });

  auto check = std::make_shared<TaskOptions>();
  auto* c = cmd->add_subcommand("check", "Score an answer to question K of `tlab task probe` (same scene, task, seed, size, camera, settings)");
  addCommonOptions(*c, *check);
  c->add_option("--question", check->question, "question number K (1-based, as printed by probe)")->capture_default_str();
  c->add_option("--answer", check->answer, "the answer text (see answer_format in the probe output)");
  c->add_flag("--missing", check->missing, "score a missing answer");
  c->add_option("--time", check->seconds, "seconds taken (over the time limit counts as missing)");

  c->callback([check] { runCheck(*check); });

  cmd->add_subcommand("list", "List the tasks and their settings")->callback(runList);
}

}  // namespace tlab::app
