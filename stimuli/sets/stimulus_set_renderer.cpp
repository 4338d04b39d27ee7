// Over 300 lines: one SetJob holds the phases of a set (align images from another renderer,
// probe, render, label, save) over shared per-unit slots, so the output never depends on --jobs.
#include "stimuli/sets/stimulus_set_renderer.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>

#include "core/file_text.hpp"
#include "core/sha256.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"
#include "stimuli/scenes/walkthrough_scene.hpp"
#include "stimuli/sets/parallel_for.hpp"
#include "stimuli/sets/booklet_pdf.hpp"
#include "stimuli/sets/external_image_alignment.hpp"
#include "stimuli/sets/label_painter.hpp"
#include "stimuli/sets/manifest.hpp"
#include "stimuli/sets/progress_bar.hpp"
#include "stimuli/sets/stimulus_set_names.hpp"
#include "stimuli/sets/stimulus_producer.hpp"

namespace tlab::stimuli {

namespace fs = std::filesystem;

render::Camera viewCamera(const render::Scene& scene, const ViewEntry& view, int width, int height) {
  const render::BoundingSphere sphere = scene.boundingSphere();
  render::Camera camera = scene.camera ? *scene.camera : render::fitCamera(sphere, float(width) / float(height));
  bool clipGiven = false;
  if (!view.camera.empty()) {
    camera = render::parseCamera(view.camera, camera);
    clipGiven = view.camera.find("near=") != std::string::npos || view.camera.find("far=") != std::string::npos;
  }
  if (view.azimuthDegrees != 0.0 || view.elevationDegrees != 0.0)
    camera = render::orbit(camera, float(view.azimuthDegrees), float(view.elevationDegrees));
  return clipGiven ? camera : render::fitClipPlanes(camera, sphere);
}

namespace {

std::string twoDigits(std::size_t i) {
  char buffer[24];
  std::snprintf(buffer, sizeof buffer, "%02zu", i);
  return buffer;
}

// glTF paths are relative to the set file.
std::string resolveSource(const std::string& source, const std::string& setFile) {
  if (source.rfind("builtin:", 0) == 0 || fs::path(source).is_absolute()) return source;
  return (fs::path(setFile).parent_path() / source).string();
}

// What a GL worker keeps between its units: its context, the label font, the last scene uploaded.
struct RenderWorker {
  std::unique_ptr<gpu::GpuContext> context;
  std::unique_ptr<LabelPainter> painter;
  std::optional<render::Renderer> renderer;
  std::size_t rendererScene = SIZE_MAX;
};

RenderWorker makeRenderWorker() {
  static std::mutex creation;  // context creation loads GL entry points into shared tables
  const std::lock_guard lock(creation);
  RenderWorker w;
  w.context = gpu::createHeadlessContext();
  w.painter = std::make_unique<LabelPainter>();
  return w;
}

// A stimulus set in two parallel phases: the questions of every (scene, view, probe set) — CPU
// only, often the longest part (exact ground truth) — then every (scene, view, style) rendered
// once and labelled for each question.
class SetJob {
 public:
  SetJob(const StimulusSetSpec& spec, const std::vector<render::Scene>& scenes, const ProbeSource& probes, const fs::path& out)
      : spec_(spec), scenes_(scenes), probes_(probes), out_(out) {
    for (std::size_t s = 0; s < spec.scenes.size(); ++s) {
      cameras_.emplace_back();
      questions_.emplace_back();
      for (std::size_t v = 0; v < spec.scenes[s].views.size(); ++v) {
        cameras_[s].push_back(viewCamera(scenes[s], spec.scenes[s].views[v], spec.width, spec.height));
        questions_[s].emplace_back(spec.scenes[s].probeSets.size());
        for (std::size_t p = 0; p < spec.scenes[s].probeSets.size(); ++p) probeUnits_.push_back({s, v, p});
        for (std::size_t st = 0; st < spec.styles.size(); ++st) renderUnits_.push_back({s, v, st});
      }
    }
    rendered_.resize(renderUnits_.size());
    external_.resize(renderUnits_.size());
    // Probing cost grows with the mesh (exact ground truth): start the largest scenes first so the
    // longest unit does not come last. Results go to fixed slots, so the order never shows.
    std::stable_sort(probeUnits_.begin(), probeUnits_.end(), [&](const Unit& a, const Unit& b) {
      return scenes_[a.scene].triangleCount() > scenes_[b.scene].triangleCount();
    });
  }

  std::size_t imageCount() const {
    std::size_t n = 0;
    for (const auto& u : renderUnits_) {
      std::size_t perStyle = 0;
      for (const auto& p : spec_.scenes[u.scene].probeSets) perStyle += p.spec.task == "points" ? 1 : std::size_t(p.spec.count);
      n += std::max<std::size_t>(1, perStyle);
    }
    return n;
  }

  void run(int jobs, ProgressBar& progress) {
    progress_ = &progress;
    parallelFor(renderUnits_.size(), jobs, makeRenderWorker, [this](std::size_t i, RenderWorker& w) { align(i, w); });
    parallelFor(probeUnits_.size(), jobs, [] { return 0; }, [this](std::size_t i, int&) { probe(probeUnits_[i]); });
    parallelFor(renderUnits_.size(), jobs, makeRenderWorker, [this](std::size_t i, RenderWorker& w) { rendered_[i] = renderUnit(i, w); });
  }

  std::vector<RenderedStimulus> results() const {
    std::vector<RenderedStimulus> all;
    for (const auto& r : rendered_) all.insert(all.end(), r.begin(), r.end());
    return all;
  }

 private:
  struct Unit {
    std::size_t scene, view, index;  // index: probe set or style
  };

  // "s01-pretzel_v1_st2-constant": scene, view and style, 1-based.
  static std::string stimulusStem(const Unit& u, const SceneEntry& scene, const StyleEntry& style) {
    std::string stem = "s";
    stem.append(twoDigits(u.scene + 1)).append("-").append(shortName(scene.source));
    stem.append("_v").append(std::to_string(u.view + 1)).append("_st").append(std::to_string(u.index + 1));
    stem.append("-").append(shortName(style.name));  // a style file: its stem
    return stem;
  }

  void probe(const Unit& u) {
    const ProbeSetEntry& entry = spec_.scenes[u.scene].probeSets[u.index];
    const ProbeView view{scenes_[u.scene], cameras_[u.scene][u.view], spec_.width, spec_.height};
    try {
      questions_[u.scene][u.view][u.index] = probes_.probe(view, entry.spec);
    } catch (const std::exception& e) {
      throw std::runtime_error(entry.place.describe() + ": " + e.what());
    }
  }

  static void useScene(RenderWorker& worker, const render::Scene& scene, std::size_t index) {
    if (worker.rendererScene == index) return;
    worker.renderer.reset();
    worker.renderer.emplace(scene);
    worker.rendererScene = index;
  }

  // Images from another renderer (an images entry of `styles`): read and compared with tlab's
  // coverage of the same view before any question is asked or picture made; else one line.
  void align(std::size_t i, RenderWorker& worker) {
    const Unit& u = renderUnits_[i];
    const StyleEntry& style = spec_.styles[u.index];
    if (style.images.empty()) return;
    const SceneEntry& scene = spec_.scenes[u.scene];
    ExternalImage& e = external_[i];
    e.path = imagesPathFor(style.images, scene, u.view);
    const std::string file = (fs::path(spec_.file).parent_path() / e.path).lexically_normal().string();
    try {
      const core::Image image = readExternalImage(file, spec_.width, spec_.height);
      useScene(worker, scenes_[u.scene], u.scene);
      const AlignmentResult result = alignWithView(*worker.renderer, cameras_[u.scene][u.view], image);
      recordGpu(*worker.context);
      if (!result.aligned) throw std::runtime_error(misalignmentMessage(file, scene.source + " view " + viewName(scene, u.view), result));
      e.iou = result.iou;
      e.sha256 = core::sha256Hex(core::readFileText(file).value_or(""));
      e.picture = opaque(image);
    } catch (const std::exception& error) {
      throw std::runtime_error(style.place.describe() + ".images: " + error.what());
    }
  }

  std::vector<RenderedStimulus> renderUnit(std::size_t i, RenderWorker& worker) {
    const Unit& u = renderUnits_[i];
    const SceneEntry& sceneEntry = spec_.scenes[u.scene];
    const StyleEntry& style = spec_.styles[u.index];
    const StimulusView view{spec_.width, spec_.height, style.name, style.settings, cameras_[u.scene][u.view]};
    core::Image image;
    if (style.images.empty()) {
      useScene(worker, scenes_[u.scene], u.scene);
      image = StimulusProducer::picture(*worker.renderer, view);
      recordGpu(*worker.context);
    } else {
      image = external_[i].picture;
    }
    const StimulusProducer producer(*worker.painter);
    const std::string stem = stimulusStem(u, sceneEntry, style);
    RenderedStimulus base;
    base.scene = u.scene, base.view = u.view, base.style = u.index, base.camera = view.camera;
    if (!style.images.empty()) base.source = {external_[i].path, external_[i].sha256, external_[i].iou};
    std::vector<RenderedStimulus> out;
    const auto& probeSets = questions_[u.scene][u.view];
    if (probeSets.empty()) {
      base.id = stem;
      out.push_back(save(base, producer.produce(image, {})));
      return out;
    }
    for (std::size_t p = 0; p < probeSets.size(); ++p)
      for (std::size_t q = 0; q < probeSets[p].size(); ++q) {
        RenderedStimulus s = base;
        s.probeSet = int(p);
        s.question = int(q);
        s.probes = probeSets[p][q];
        s.id = stem + "_p" + std::to_string(p + 1) + "_q" + std::to_string(q + 1);
        out.push_back(save(s, producer.produce(image, s.probes.marks)));
      }
    return out;
  }

  // The GL that rendered the set, for the manifest (every worker runs the same --gl choice).
  void recordGpu(const gpu::GpuContext& context) {
    const std::lock_guard lock(gpuMutex_);
    if (gpu_.renderer.empty()) gpu_ = context.info();
  }

 public:
  gpu::GpuInfo gpu() const { return gpu_; }

 private:
  RenderedStimulus save(RenderedStimulus s, const ProducedStimulus& produced) {
    s.image = "images/" + s.id + ".png";
    s.sha256 = produced.sha256;
    core::writeFileAtomically((out_ / s.image).string(), produced.png);
    progress_->advance();
    return s;
  }

  const StimulusSetSpec& spec_;
  const std::vector<render::Scene>& scenes_;
  const ProbeSource& probes_;
  fs::path out_;
  ProgressBar* progress_ = nullptr;
  std::mutex gpuMutex_;
  gpu::GpuInfo gpu_;
  std::vector<std::vector<render::Camera>> cameras_;                          // [scene][view]
  std::vector<std::vector<std::vector<std::vector<ProbeQuestion>>>> questions_;  // [scene][view][probe set]
  std::vector<Unit> probeUnits_, renderUnits_;
  std::vector<std::vector<RenderedStimulus>> rendered_;                      // per render unit
  struct ExternalImage {
    core::Image picture;  // as shown (opaque)
    std::string path;     // relative to the set file, as its images path names it
    std::string sha256;   // of the PNG file
    double iou = 0.0;
  };
  std::vector<ExternalImage> external_;                                      // per render unit (images entries)
};

void validateTasks(const StimulusSetSpec& spec, const ProbeSource& probes) {
  const auto known = probes.taskNames();
  for (const auto& scene : spec.scenes)
    for (const auto& p : scene.probeSets)
      if (std::find(known.begin(), known.end(), p.spec.task) == known.end()) {
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        throw std::runtime_error(p.place.describe() + ": unknown task '" + p.spec.task + "' (known: " + list + ")");
      }
}

std::vector<render::Scene> buildScenes(const StimulusSetSpec& spec, const std::vector<render::BuiltinSceneSpec>& catalog) {
  std::vector<render::Scene> scenes;
  for (const auto& entry : spec.scenes) {
    try {
      scenes.push_back(render::loadScene(resolveSource(entry.source, spec.file), catalog));
      render::requireTriangles(scenes.back(), entry.source);
    } catch (const std::exception& e) {
      throw std::runtime_error(entry.place.describe() + ": " + e.what());
    }
  }
  return scenes;
}

// Walkthrough scenes come with their top-down plan for answering (Elmqvist T3).
std::vector<std::pair<std::size_t, std::string>> writeFloorPlans(const StimulusSetSpec& spec, const fs::path& out) {
  std::vector<std::pair<std::size_t, std::string>> plans;
  for (std::size_t s = 0; s < spec.scenes.size(); ++s) {
    const auto image = walkthroughFloorPlanForSource(spec.scenes[s].source);
    if (!image) continue;
    const std::string path = "floor-plans/s" + twoDigits(s + 1) + "-" + shortName(spec.scenes[s].source) + ".png";
    fs::create_directories(out / "floor-plans");
    core::writeFileAtomically((out / path).string(), core::encodePng(*image));
    plans.emplace_back(s, path);
  }
  return plans;
}

}  // namespace

StimulusSetResult StimulusSetRenderer::render(const StimulusSetSpec& spec, const StimulusSetOptions& options) const {
  validateTasks(spec, probes_);
  const std::vector<render::Scene> scenes = buildScenes(spec, catalog_);
  const fs::path out(options.outputDir);
  fs::create_directories(out / "images");
  SetJob job(spec, scenes, probes_, out);
  {
    ProgressBar bar("stimuli " + spec.name, job.imageCount(), options.progress);
    job.run(options.jobs, bar);
  }
  StimulusSetResult result;
  result.stimuli = job.results();
  const auto plans = writeFloorPlans(spec, out);
  result.gpu = job.gpu();
  result.manifest = stimulusSetManifest(spec, scenes, result.stimuli, plans, result.gpu, options.tlabVersion);
  result.manifestPath = (out / "manifest.json").string();
  const std::string text = result.manifest.dump(2) + "\n";
  core::writeFileAtomically(result.manifestPath, std::vector<std::uint8_t>(text.begin(), text.end()));
  if (spec.booklet) {
    result.bookletPath = (out / "booklet.pdf").string();
    writeBookletPdf(result.bookletPath, spec, result.stimuli, out.string());
  }
  return result;
}

}  // namespace tlab::stimuli
