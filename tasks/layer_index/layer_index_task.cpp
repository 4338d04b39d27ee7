#include "tasks/layer_index/layer_index_task.hpp"

#include <algorithm>

#include "core/seeded_random.hpp"
#include "tasks/layer_index/layer_ground_truth.hpp"
#include "tasks/probe_helpers.hpp"
#include "tasks/ray_layer_caster.hpp"
#include "tasks/layer_index/silhouette_edges.hpp"

namespace tlab::tasks {

std::vector<SettingSpec> LayerIndexTask::settingSpecs() const {
  auto specs = commonSettings();
  specs.push_back(SettingSpec::count("min-layer", "1", "smallest layer number asked for", 1, 1000));
  specs.push_back(SettingSpec::count("max-layer", "0", "largest layer number asked for (0: no limit)", 0, 1000));
  specs.push_back(SettingSpec::number("min-separation-px", "12", "minimum pixel distance between the probes of different questions", 0, 100000));
  specs.push_back(SettingSpec::number("margin-px", "8", "minimum pixel distance of a probe from the image border", 0, 100000));
  specs.push_back(SettingSpec::count("attempts", "400", "candidate probes tried per question before giving up", 1, 1000000));
  return specs;
}

namespace {

// A candidate: a point on a silhouette edge chosen by length, away from the edge's ends.
struct Candidate {
  glm::dvec3 point;
  const SilhouetteEdge* edge;
};

class SilhouetteSampler {
 public:
  explicit SilhouetteSampler(const std::vector<SilhouetteEdge>& edges) : edges_(edges) {
    double sum = 0.0;
    for (const auto& e : edges_) cumulative_.push_back(sum += e.length());
  }
  bool empty() const { return cumulative_.empty() || cumulative_.back() <= 0.0; }
  Candidate sample(core::SeededRandom& random) const {
    const double u = double(random.uniform()) * cumulative_.back();
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), u);
    const auto& e = edges_[std::min<std::size_t>(std::size_t(it - cumulative_.begin()), edges_.size() - 1)];
    const double t = 0.25 + 0.5 * double(random.uniform());
    return {glm::mix(e.p0, e.p1, t), &e};
  }

 private:
  const std::vector<SilhouetteEdge>& edges_;
  std::vector<double> cumulative_;
};

}  // namespace

std::vector<Question> LayerIndexTask::probe(const ProbeRequest& request) const {
  requirePositiveCount(name(), request.count);
  const TaskSettings& s = request.settings;
  const int minLayer = int(s.number("min-layer")), maxLayer = int(s.number("max-layer"));
  const double separation = s.number("min-separation-px"), margin = s.number("margin-px");
  const int attempts = int(s.number("attempts"));

  const ViewGeometry view(request.camera, request.width, request.height);
  const auto welded = weldSceneObjects(request.scene);
  const auto edges = silhouetteEdges(welded, view.eye());
  const SilhouetteSampler sampler(edges);
  const RayLayerCaster caster(request.scene);
  const LayerGroundTruth truth(caster, view, double(request.scene.boundingSphere().radius));

  core::SeededRandom random(request.seed);
  std::vector<Question> questions;
  std::vector<glm::dvec2> taken;
  for (int q = 0; q < request.count; ++q) {
    bool found = false;
    for (int a = 0; a < attempts && !found && !sampler.empty(); ++a) {
      const Candidate c = sampler.sample(random);
      if (!view.inImage(c.point, margin)) continue;
      const glm::dvec2 pixel = view.project(c.point);
      const double gap = nearestPixelDistance(pixel, taken);
      if (gap < separation) continue;
      const LayerVerdict v = truth.verdict(c.point);
      if (!v.unambiguous() || v.layer < minLayer || (maxLayer > 0 && v.layer > maxLayer)) continue;
      Question question;
      question.task = name();
      question.number = q + 1;
      question.text = "On which layer is the surface silhouette at point A? (1 = the front layer)";
      question.textKey = "question.layer_index";
      question.answerKind = AnswerKind::LayerNumber;
      question.points = {probePoint(view, "A", "probe", c.point, c.edge->object)};
      question.truth = std::int64_t(v.layer);
      question.timeLimitSeconds = s.number("time-limit");
      question.checks = {{"pixels of the 3x3 neighbourhood with the same layer", double(v.agreeingPixels), double(v.checkedPixels)}};
      if (!taken.empty()) question.checks.push_back({"pixel distance to earlier probes", gap, separation});
      question.measurements = {{"depth", view.depth(c.point)},
                               {"depth-tolerance", v.depthTolerance},
                               {"on-boundary", c.edge->kind == SilhouetteKind::Boundary ? 1.0 : 0.0}};
      questions.push_back(std::move(question));
      taken.push_back(pixel);
      found = true;
    }
    if (!found)
      throwTooFew(name(), questions.size(), request.count,
                  "silhouette points that are inside the image, unambiguous and within the layer range; try fewer questions, "
                  "a smaller min-separation-px or another view");
  }
  return questions;
}

}  // namespace tlab::tasks
