#include "tasks/nearest_point/nearest_point_task.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/seeded_random.hpp"
#include "tasks/nearest_point/geodesic_distances.hpp"
#include "tasks/nearest_point/nearest_point_candidates.hpp"
#include "tasks/probe_helpers.hpp"

namespace tlab::tasks {

std::vector<SettingSpec> NearestPointTask::settingSpecs() const {
  auto specs = commonSettings();
  specs.push_back(SettingSpec::count("candidates", "3", "number of candidate points (at least 2)", 2, 6));
  specs.push_back(SettingSpec::number("margin", "0.1", "second-nearest geodesic distance must be ≥ (1 + margin) × nearest", 0, 100));
  specs.push_back(SettingSpec::number("euclidean-trap-share", "0.5", "share of questions whose Euclidean-nearest candidate is not the geodesic-nearest", 0, 1));
  specs.push_back(SettingSpec::number("min-pixel-gap", "16", "minimum pixel distance between any two points of a question", 0, 100000));
  specs.push_back(SettingSpec::number("margin-px", "8", "minimum pixel distance of a point from the image border", 0, 100000));
  specs.push_back(SettingSpec::number("neighbourhood", "1", "candidates lie within this Euclidean distance of A and within twice it along the surface "
                                           "(a fraction of the scene's bounding radius; 0: anywhere)", 0, 1000));
  specs.push_back(SettingSpec::count("pool", "32", "surface points sampled per start point A", 2, 100000));
  specs.push_back(SettingSpec::count("sources", "64", "start points A tried per question before giving up", 1, 1000000));
  return specs;
}

// The largest patch the exact algorithm may run on for one start point A: a fifth of the mesh, at
// least 4 000 faces (its cost grows faster than the patch: on the pretzel, 0.1 s for 2.7 K faces,
// several seconds for 38 K). A start point needing more is passed over for another.
std::size_t faceBudget(const GeodesicDistances& g) { return std::max<std::size_t>(4000, g.faceCount() / 5); }

// How often the exactness radius is doubled before another start point A is tried.
constexpr int kWidenings = 1;
constexpr double kWidening = 2.0;

bool wantsEuclideanTrap(int k, double share) {
  return std::floor(double(k + 1) * share + 1e-9) > std::floor(double(k) * share + 1e-9);
}

namespace {

using namespace nearest;

struct NearestSettings {
  int count;
  double margin, share, pixelGap, borderPx;
  int poolSize, sources;
  double reach;  // the neighbourhood in 3-D (infinite: anywhere)
  double timeLimit;
};

NearestSettings nearestSettings(const ProbeRequest& request) {
  const TaskSettings& s = request.settings;
  NearestSettings f;
  f.count = int(s.number("candidates"));
  f.margin = s.number("margin");
  f.share = s.number("euclidean-trap-share");
  f.pixelGap = s.number("min-pixel-gap");
  f.borderPx = s.number("margin-px");
  f.poolSize = int(s.number("pool"));
  f.sources = int(s.number("sources"));
  const double neighbourhood = s.number("neighbourhood") * double(request.scene.boundingSphere().radius);
  f.reach = neighbourhood > 0.0 ? neighbourhood : std::numeric_limits<double>::infinity();
  f.timeLimit = s.number("time-limit");
  return f;
}

// The scene's objects as welded meshes with their geodesic distances and area samplers, and the
// seeded, area-weighted choice of visible surface points on them. Not copied: the geodesics and
// samplers refer to the meshes.
struct Surfaces {
  const ViewGeometry& view;
  double borderPx;
  core::SeededRandom& random;
  const std::vector<WeldedMesh> welded;
  std::vector<GeodesicDistances> geodesics;
  std::vector<SurfaceSampler> samplers;
  double totalArea = 0.0;

  Surfaces(const render::Scene& scene, const ViewGeometry& v, double border, core::SeededRandom& r)
      : view(v), borderPx(border), random(r), welded(weldSceneObjects(scene)) {
    for (const auto& w : welded) {
      geodesics.emplace_back(w);
      samplers.emplace_back(w);
      totalArea += samplers.back().totalArea();
    }
  }
  Surfaces(const Surfaces&) = delete;
  Surfaces& operator=(const Surfaces&) = delete;

  // An object, with probability proportional to its area.
  std::size_t pickObject() {
    double u = double(random.uniform()) * totalArea;
    for (std::size_t o = 0; o < samplers.size(); ++o) {
      if (u < samplers[o].totalArea()) return o;
      u -= samplers[o].totalArea();
    }
    return samplers.size() - 1;
  }
  // A point of object o inside the image where the geodesics are known (64 tries).
  bool visibleSample(std::size_t o, SurfacePoint* out) {
    for (int i = 0; i < 64; ++i) {
      const SurfacePoint p = samplers[o].sample(random);
      if (geodesics[o].hasTriangle(p.triangle) && view.inImage(p.position(welded[o]), borderPx)) {
        *out = p;
        return true;
      }
    }
    return false;
  }
};

// A start point A on object o.
struct Start {
  std::size_t o;
  SurfacePoint a;
  glm::dvec3 world;
  glm::dvec2 pixel;
};

// The pool: visible points apart from A on screen, within the neighbourhood in 3-D and (by the
// edge-path upper bound) within twice it on the surface — which keeps the exact geodesic
// computation on a patch around A (GeodesicDistances). Their upper bounds and 3-D distances.
struct Targets {
  std::vector<SurfacePoint> points;
  std::vector<double> upper, straight;
};

Targets targetsAround(Surfaces& sf, const Start& st, const NearestSettings& f) {
  std::vector<SurfacePoint> near;
  for (int i = 0; i < f.poolSize; ++i)
    for (int attempt = 0; attempt < 16; ++attempt) {
      SurfacePoint t;
      if (!sf.visibleSample(st.o, &t)) break;
      const glm::dvec3 tWorld = t.position(sf.welded[st.o]);
      if (glm::length(tWorld - st.world) > f.reach || glm::length(sf.view.project(tWorld) - st.pixel) < f.pixelGap) continue;
      near.push_back(t);
      break;
    }
  const auto bounds = sf.geodesics[st.o].edgePathUpperBounds(st.a, near);
  Targets t;
  for (std::size_t i = 0; i < near.size(); ++i)
    if (bounds[i] && *bounds[i] <= 2.0 * f.reach) {
      t.points.push_back(near[i]);
      t.upper.push_back(*bounds[i]);
      t.straight.push_back(glm::length(near[i].position(sf.welded[st.o]) - st.world));
    }
  return t;
}

// Exact up to (1 + margin) × the smallest head bound: that head (and any other point within the
// radius) is then known exactly and can be the nearest; every point beyond is provably ≥ (1 +
// margin) × its distance, which is all a question needs. So the exact algorithm runs on a small
// patch around A — its cost grows faster than the patch's area (seen on the toroid: 0.05 s for
// 1.5 K faces, 14 s for all 52 K). When no question can be formed, the radius is widened once
// (doubled, at most to the largest bound, where every distance is exact) before another A is tried.
std::optional<Choice> chooseWithinRadius(Surfaces& sf, const Start& st, const Targets& t, double nearestBound,
                                         const NearestSettings& f, bool wantTrap) {
  const GeodesicDistances& geodesics = sf.geodesics[st.o];
  const double widest = (1.0 + f.margin) * *std::max_element(t.upper.begin(), t.upper.end());
  std::optional<Choice> choice;
  double cap = (1.0 + f.margin) * nearestBound;
  for (int round = 0;; ++round, cap = std::min(widest, kWidening * cap)) {
    if (geodesics.patchFaces(st.a, cap) > faceBudget(geodesics)) break;  // too costly: another A
    const auto distances = geodesics.fromSourceWithin(st.a, t.points, cap);
    std::vector<PoolPoint> pool;
    for (std::size_t i = 0; i < t.points.size(); ++i) {
      if (!distances[i].reachable) continue;  // another connected component
      const glm::dvec3 w = t.points[i].position(sf.welded[st.o]);
      pool.push_back({t.points[i], w, sf.view.project(w), distances[i].lowerBound, t.straight[i], distances[i].exact.has_value()});
    }
    choice = chooseCandidates(pool, f.count, f.margin, wantTrap, f.pixelGap, sf.random);
    if (choice || cap >= widest || round == kWidenings) break;
  }
  return choice;
}

Question nearestQuestion(const std::string& task, int number, const ViewGeometry& view, const Start& st, const Choice& choice,
                         const NearestSettings& f, bool wantTrap) {
  static const std::string labels = "XYZUVW";
  Question question;
  question.task = task;
  question.number = number;
  question.text = "Which of the marked points is nearest to A when walking on the surface?";
  question.textKey = "question.nearest_point";
  question.answerKind = AnswerKind::Label;
  question.points.push_back(probePoint(view, "A", "given", st.world, int(st.o)));
  std::vector<double> geo, euc;
  for (std::size_t i = 0; i < choice.candidates.size(); ++i) {
    const auto& c = choice.candidates[i];
    const std::string label(1, labels[i]);
    question.points.push_back(probePoint(view, label, "candidate", c.world, int(st.o)));
    // Exact for the nearest (and any candidate within the exactness radius); for the others a
    // proven lower bound, which is what the margin needs.
    question.measurements.push_back({(c.exact ? "geodesic:" : "geodesic-lower-bound:") + label, c.geodesic});
    question.measurements.push_back({"euclidean:" + label, c.euclidean});
    geo.push_back(c.geodesic);
    euc.push_back(c.euclidean);
  }
  question.truth = std::string(1, labels[argMin(geo)]);
  question.timeLimitSeconds = f.timeLimit;
  question.checks = {{"geodesic second-nearest / nearest - 1", choice.geodesicMargin, f.margin},
                     {"euclidean-nearest differs from geodesic-nearest", choice.trap ? 1.0 : 0.0, wantTrap ? 1.0 : 0.0}};
  if (wantTrap) question.checks.push_back({"euclidean second-nearest / nearest - 1", choice.euclideanMargin, f.margin});
  return question;
}

// One start point A tried: its pool, the bounds that say which points can head a question, and
// the candidates chosen within the exactness radius; nothing when A gives no question.
std::optional<Question> questionFromStart(const std::string& task, int number, bool wantTrap, const NearestSettings& f,
                                          Surfaces& sf) {
  Start st;
  st.o = sf.pickObject();
  if (!sf.visibleSample(st.o, &st.a)) return std::nullopt;
  st.world = st.a.position(sf.welded[st.o]);
  st.pixel = sf.view.project(st.world);
  const Targets t = targetsAround(sf, st, f);
  if (t.points.size() < std::size_t(f.count)) return std::nullopt;
  const std::vector<double> heads = headBounds(t.upper, t.straight, f.margin, wantTrap);
  if (heads.empty()) return std::nullopt;  // no question possible from this A
  const std::optional<Choice> choice = chooseWithinRadius(sf, st, t, heads.front(), f, wantTrap);
  if (!choice) return std::nullopt;
  return nearestQuestion(task, number, sf.view, st, *choice, f, wantTrap);
}

}  // namespace

std::vector<Question> NearestPointTask::probe(const ProbeRequest& request) const {
  requirePositiveCount(name(), request.count);
  const NearestSettings f = nearestSettings(request);
  const ViewGeometry view(request.camera, request.width, request.height);
  core::SeededRandom random(request.seed);
  Surfaces surfaces(request.scene, view, f.borderPx, random);
  if (surfaces.totalArea <= 0.0) throw std::runtime_error(name() + ": the scene has no surface area");

  std::vector<Question> questions;
  for (int q = 0; q < request.count; ++q) {
    const bool wantTrap = wantsEuclideanTrap(q, f.share);
    bool found = false;
    for (int src = 0; src < f.sources && !found; ++src) {
      std::optional<Question> question = questionFromStart(name(), q + 1, wantTrap, f, surfaces);
      if (!question) continue;
      questions.push_back(std::move(*question));
      found = true;
    }
    if (!found)
      throwTooFew(name(), questions.size(), request.count,
                  std::string("candidates unique by the geodesic margin") +
                      (wantTrap ? " whose Euclidean-nearest is another candidate (impossible on convex surfaces such as a "
                                  "sphere; --set euclidean-trap-share=0)"
                                : "") +
                      "; try a smaller margin or another view");
  }
  return questions;
}

}  // namespace tlab::tasks
