#include "tasks/follow_boundary/follow_boundary_task.hpp"

#include <algorithm>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>

#include "core/seeded_random.hpp"
#include "tasks/follow_boundary/boundary_arc.hpp"
#include "tasks/follow_boundary/boundary_loops.hpp"
#include "tasks/probe_helpers.hpp"

namespace tlab::tasks {

std::vector<SettingSpec> FollowBoundaryTask::settingSpecs() const {
  auto specs = commonSettings();
  specs.push_back(SettingSpec::count("marks", "4", "number of marks besides A and B (at least 2: some on the way, some off)", 2, 100));
  specs.push_back(SettingSpec::number("margin", "0.1", "the other way must be longer than the shortest by this fraction", 0, 100));
  specs.push_back(SettingSpec::number("min-arc-gap", "0.04", "minimum arc distance between any two points of a loop, as a fraction of its length", 0, 1));
  specs.push_back(SettingSpec::number("min-pixel-gap", "12", "minimum pixel distance between any two points of a question", 0, 100000));
  specs.push_back(SettingSpec::number("margin-px", "8", "minimum pixel distance of a point from the image border", 0, 100000));
  specs.push_back(SettingSpec::count("attempts", "400", "candidate questions tried per question before giving up", 1, 1000000));
  return specs;
}

namespace {

struct Mark {
  std::size_t loop;
  double arc;
  glm::dvec3 world;
};

// A point at a random arc position of `loop` that keeps `minGap` arc length from `others` on the
// same loop; false if the random position is too close.
bool placeMark(const std::vector<BoundaryLoop>& loops, std::size_t loop, double arc, double minGapFraction,
               const std::vector<Mark>& others, Mark* out) {
  const BoundaryLoop& l = loops[loop];
  const double a = l.wrap(arc), gap = minGapFraction * l.length();
  for (const auto& o : others)
    if (o.loop == loop && std::min(forwardArcLength(a, o.arc, l.length()), forwardArcLength(o.arc, a, l.length())) < gap)
      return false;
  *out = {loop, a, l.pointAt(a)};
  return true;
}

std::size_t pickByLength(const std::vector<BoundaryLoop>& loops, const std::vector<std::size_t>& among, core::SeededRandom& random) {
  double total = 0.0;
  for (const auto i : among) total += loops[i].length();
  double u = double(random.uniform()) * total;
  for (const auto i : among) {
    if (u < loops[i].length()) return i;
    u -= loops[i].length();
  }
  return among.back();
}

struct FollowSettings {
  int markCount;
  double margin, arcGap, pixelGap, borderPx;
  int attempts;
  double timeLimit;
};

FollowSettings followSettings(const TaskSettings& s) {
  FollowSettings f;
  f.markCount = int(s.number("marks"));
  f.margin = s.number("margin");
  f.arcGap = s.number("min-arc-gap");
  f.pixelGap = s.number("min-pixel-gap");
  f.borderPx = s.number("margin-px");
  f.attempts = int(s.number("attempts"));
  f.timeLimit = s.number("time-limit");
  return f;
}

// A and B on one loop, the shortest way between them and the marks: [0] is A, [1] is B.
struct Candidate {
  std::size_t loop;
  BoundaryArc way;
  double otherWay;
  std::vector<Mark> marks;
};

// Marks besides A and B: at least one on the way and one off it (on the other way or another loop).
bool placeOtherMarks(const std::vector<BoundaryLoop>& loops, const std::vector<std::size_t>& usable, const FollowSettings& f,
                     core::SeededRandom& random, Candidate& c) {
  const BoundaryArc& way = c.way;
  const int onWay = 1 + int(random.below(std::uint32_t(f.markCount - 1)));
  Mark m = c.marks.back();
  bool placed = true;
  for (int k = 0; k < f.markCount && placed; ++k) {
    double arc;
    std::size_t markLoop = c.loop;
    if (k < onWay) {
      arc = way.from + way.direction * way.length * double(random.uniform());
    } else if (usable.size() > 1 && random.below(2) == 0) {
      markLoop = usable[random.below(std::uint32_t(usable.size() - 1))];
      if (markLoop == c.loop) markLoop = usable.back();  // any loop but A's
      arc = double(random.uniform()) * loops[markLoop].length();
    } else {
      arc = way.from - way.direction * c.otherWay * double(random.uniform());
    }
    placed = placeMark(loops, markLoop, arc, f.arcGap, c.marks, &m);
    c.marks.push_back(m);
  }
  return placed;
}

// A and B: B at a fraction u of the loop from A, the shorter way ≤ the longer / (1 + margin);
// then the other marks. Nothing when a draw misses.
std::optional<Candidate> drawCandidate(const std::vector<BoundaryLoop>& loops, const std::vector<std::size_t>& usable,
                                       const FollowSettings& f, core::SeededRandom& random) {
  const std::size_t loop = pickByLength(loops, usable, random);
  const BoundaryLoop& l = loops[loop];
  const double arcA = double(random.uniform()) * l.length();
  const double u = 0.1 + 0.8 * double(random.uniform());
  const BoundaryArc way = shortestBoundaryArc(arcA, arcA + u * l.length(), l.length());
  const double otherWay = l.length() - way.length;
  if (otherWay < (1.0 + f.margin) * way.length) return std::nullopt;
  Candidate c{loop, way, otherWay, {}};
  Mark m;
  placeMark(loops, loop, arcA, 0.0, c.marks, &m);
  c.marks.push_back(m);
  if (!placeMark(loops, loop, arcA + u * l.length(), f.arcGap, c.marks, &m)) return std::nullopt;
  c.marks.push_back(m);
  if (!placeOtherMarks(loops, usable, f, random, c)) return std::nullopt;
  return c;
}

// Every point inside the image and apart from the others on screen: the smallest pixel distance
// between them, or nothing.
std::optional<double> screenGap(const ViewGeometry& view, const std::vector<Mark>& marks, const FollowSettings& f) {
  std::vector<glm::dvec2> pixels;
  double smallestGap = 1e9;
  bool visible = true;
  for (const auto& mk : marks) {
    if (!view.inImage(mk.world, f.borderPx)) visible = false;
    const glm::dvec2 p = view.project(mk.world);
    smallestGap = std::min(smallestGap, nearestPixelDistance(p, pixels));
    pixels.push_back(p);
  }
  if (!visible || smallestGap < f.pixelGap) return std::nullopt;
  return smallestGap;
}

// The question of a candidate, its marks besides A and B labelled in the order `order`.
Question boundaryQuestion(const std::string& task, int number, const ViewGeometry& view, const std::vector<BoundaryLoop>& loops,
                          const Candidate& c, const std::vector<std::size_t>& order, double smallestGap, const FollowSettings& f) {
  static const std::string labelNames = "CDEFGHJKLMNPQRSTUVWXYZ";
  const BoundaryLoop& l = loops[c.loop];
  Question question;
  question.task = task;
  question.number = number;
  question.text = "Follow the shortest way along the surface boundary from A to B. Which marked points do you meet on the way?";
  question.textKey = "question.follow_boundary";
  question.answerKind = AnswerKind::LabelSet;
  question.points.push_back(probePoint(view, "A", "start", c.marks[0].world, l.object()));
  question.points.push_back(probePoint(view, "B", "end", c.marks[1].world, l.object()));
  std::set<std::string> met;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Mark& mk = c.marks[order[k]];
    const std::string label(1, labelNames[k % labelNames.size()]);
    question.points.push_back(probePoint(view, label, "mark", mk.world, loops[mk.loop].object()));
    if (mk.loop == c.loop && c.way.contains(mk.arc)) met.insert(label);
  }
  question.truth = met;
  question.timeLimitSeconds = f.timeLimit;
  question.checks = {{"other way / shortest way - 1", c.otherWay / c.way.length - 1.0, f.margin},
                     {"smallest pixel distance between points", smallestGap, f.pixelGap}};
  question.measurements = {{"shortest-way-length", c.way.length}, {"other-way-length", c.otherWay}, {"loop-length", l.length()}};
  return question;
}

}  // namespace

std::vector<Question> FollowBoundaryTask::probe(const ProbeRequest& request) const {
  requirePositiveCount(name(), request.count);
  const FollowSettings f = followSettings(request.settings);
  const ViewGeometry view(request.camera, request.width, request.height);
  std::vector<BoundaryLoop> loops;
  const auto welded = weldSceneObjects(request.scene);
  for (std::size_t o = 0; o < welded.size(); ++o)
    for (auto& l : boundaryLoops(welded[o], int(o))) loops.push_back(std::move(l));
  std::vector<std::size_t> usable;
  for (std::size_t i = 0; i < loops.size(); ++i)
    if (loops[i].length() > 0.0) usable.push_back(i);
  if (usable.empty()) throw std::runtime_error(name() + ": the scene has no surface boundary (no open surface)");

  core::SeededRandom random(request.seed);
  std::vector<Question> questions;
  for (int q = 0; q < request.count; ++q) {
    bool found = false;
    for (int a = 0; a < f.attempts && !found; ++a) {
      const std::optional<Candidate> c = drawCandidate(loops, usable, f, random);
      if (!c) continue;
      const std::optional<double> smallestGap = screenGap(view, c->marks, f);
      if (!smallestGap) continue;
      // Shuffle the marks so that their labels say nothing about the way.
      std::vector<std::size_t> order(c->marks.size() - 2);
      std::iota(order.begin(), order.end(), 2);
      for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[random.below(std::uint32_t(i))]);
      questions.push_back(boundaryQuestion(name(), q + 1, view, loops, *c, order, *smallestGap, f));
      found = true;
    }
    if (!found)
      throwTooFew(name(), questions.size(), request.count,
                  "boundary points inside the image and apart from each other; try fewer marks, smaller gaps or another view");
  }
  return questions;
}

}  // namespace tlab::tasks
