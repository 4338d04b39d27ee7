#pragma once
// Where the marked points of a stimulus and its question come from. The stimuli library knows only
// this interface and one source of its own (SurfacePointProbes: labelled random visible surface
// points, no question); the application plugs in the tasks library's questions with their exact
// ground truth — the hook that keeps tasks/ and stimuli/ siblings: neither includes the other.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "renderer/scene/camera.hpp"
#include "renderer/scene/scene.hpp"

namespace tlab::stimuli {

// One probe set of a stimulus-set file: which task asks, how many questions, its seed, settings.
struct ProbeSetSpec {
  std::string task;                   // "points" (SurfacePointProbes) or a task name
  int count = 1;                      // questions (for "points": marked points)
  std::uint64_t seed = 1;
  std::vector<std::string> settings;  // key=value, passed to the task
};

// A marked point as drawn on the image: pixel is continuous (row 0 = top).
struct ProbeMark {
  std::string label;
  std::string role;
  glm::dvec3 world{0.0};
  glm::dvec2 pixel{0.0};
};

struct ProbeQuestion {
  std::string text;
  std::vector<ProbeMark> marks;
  std::string answerFormat;           // how to answer, for the booklet
  bool printable = true;              // false: the answer cannot be given on paper (the booklet says so)
  nlohmann::json groundTruth;         // null when the source has none
};

struct ProbeView {
  const render::Scene& scene;
  render::Camera camera;
  int width = 512;
  int height = 512;
};

class ProbeSource {
 public:
  virtual ~ProbeSource() = default;
  // The task names this source answers (for validating set files).
  virtual std::vector<std::string> taskNames() const = 0;
  // Pure: the same view and spec give the same questions. Throws std::runtime_error saying why
  // no questions could be made.
  virtual std::vector<ProbeQuestion> probe(const ProbeView& view, const ProbeSetSpec& spec) const = 0;
};

// "points": `count` surface points, area-weighted and seeded, that project inside the image with a
// margin (no visibility test: in a transparent scene every layer shows), at least a marker's width
// apart, labelled A, B, C, ... No ground truth.
class SurfacePointProbes final : public ProbeSource {
 public:
  std::vector<std::string> taskNames() const override { return {"points"}; }
  std::vector<ProbeQuestion> probe(const ProbeView& view, const ProbeSetSpec& spec) const override;
};

// Pixel position (continuous, row 0 = top) of a world point, and whether it is in front of the camera.
glm::dvec2 projectToPixel(const render::Camera& camera, int width, int height, const glm::dvec3& world, bool* inFront = nullptr);

// "A", "B", ..., "Z", "AA", ...
std::string probeLabel(std::size_t index);

}  // namespace tlab::stimuli
