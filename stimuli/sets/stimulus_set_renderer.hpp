#pragma once
// Renders a stimulus set: every (scene, view, style, probe set, question) to a labelled PNG, the
// manifest (parameters, seeds, cameras, probe positions in 2-D and 3-D, ground truth when the probe
// source has it, SHA-256 of every image), the floor plans of walkthrough scenes, and the PDF
// booklet. The same spec gives the same bytes, whatever `jobs` is: every (scene, view) is rendered
// on its own (one GL context per worker thread) and the outputs are assembled in a fixed order.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/gpu/gpu_context.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "stimuli/sets/probe_source.hpp"
#include "stimuli/sets/stimulus_set_spec.hpp"

namespace tlab::stimuli {

struct StimulusSetOptions {
  std::string outputDir;
  int jobs = 1;
  bool progress = true;   // a progress bar on stderr when it is a terminal
  std::string tlabVersion = "unknown";  // the version and git revision that render it (the manifest's tlab_version)
};

// An image from another renderer as it entered the set: its path relative to the set file, the
// SHA-256 of the PNG file as given, and its overlap with tlab's coverage of the view.
struct SourceImage {
  std::string path;
  std::string sha256;
  double iou = 0.0;
};

// One image of the set.
struct RenderedStimulus {
  std::string id;          // s01-pretzel_v1_st1-constant_p1_q1
  std::string image;       // relative to the output folder
  std::string sha256;
  std::size_t scene = 0, view = 0, style = 0;
  int probeSet = -1, question = -1;  // -1: unlabelled
  render::Camera camera;
  ProbeQuestion probes;    // marks, text, ground truth (empty marks when unlabelled)
  SourceImage source;      // the image from another renderer it shows (images entries; else empty)
};

struct StimulusSetResult {
  std::vector<RenderedStimulus> stimuli;
  nlohmann::json manifest;
  std::string manifestPath, bookletPath;  // bookletPath empty when no booklet was asked for
  gpu::GpuInfo gpu;                       // the GL that rendered it (empty when nothing was rendered)
};

class StimulusSetRenderer {
 public:
  StimulusSetRenderer(std::vector<render::BuiltinSceneSpec> catalog, const ProbeSource& probes)
      : catalog_(std::move(catalog)), probes_(probes) {}
  // Throws std::runtime_error naming the set file, line and field of the entry that failed.
  StimulusSetResult render(const StimulusSetSpec& spec, const StimulusSetOptions& options) const;

 private:
  std::vector<render::BuiltinSceneSpec> catalog_;
  const ProbeSource& probes_;
};

// The camera of a view: the scene's own (else fitted), a camera string on top, orbited.
render::Camera viewCamera(const render::Scene& scene, const ViewEntry& view, int width, int height);

}  // namespace tlab::stimuli
