#include "stimuli/surfaces/advancing_front.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tlab::stimuli {

namespace {

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

// A particle of the front: where it is, its seed parameter s, its latest mesh vertex and track.
struct FrontParticle {
  glm::dvec3 position{0.0};
  double s = 0.0;
  std::uint32_t vertex = kNoVertex;
  std::uint32_t track = kNoVertex;
};
using FrontRun = std::vector<FrontParticle>;  // consecutive particles, s increasing

double bendDegrees(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 u = b - a, v = c - b;
  const double lu = glm::length(u), lv = glm::length(v);
  if (lu <= 0.0 || lv <= 0.0) return 0.0;
  return std::acos(std::clamp(glm::dot(u, v) / (lu * lv), -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

// Linear interpolation of the front at parameter s (the run brackets s).
glm::dvec3 positionOnRun(const FrontRun& run, double s) {
  const auto it = std::lower_bound(run.begin(), run.end(), s, [](const FrontParticle& p, double v) { return p.s < v; });
  if (it == run.begin()) return run.front().position;
  if (it == run.end()) return run.back().position;
  const FrontParticle& hi = *it;
  const FrontParticle& lo = *(it - 1);
  const double span = hi.s - lo.s;
  return span > 0.0 ? glm::mix(lo.position, hi.position, (s - lo.s) / span) : lo.position;
}

// Accumulates the mesh and the particle tracks.
class SurfaceAssembly {
 public:
  SurfaceAssembly(IntegralSurface& out, double tearLength) : out_(out), tearLength2_(float(tearLength * tearLength)) {}

  void addVertex(FrontParticle& p, double t) {
    if (p.track == kNoVertex) {
      p.track = std::uint32_t(out_.tracks.size());
      out_.tracks.emplace_back();
    }
    p.vertex = std::uint32_t(out_.mesh.positions.size());
    out_.mesh.positions.push_back(glm::vec3(p.position));
    out_.mesh.st.push_back(glm::vec2(float(p.s), float(t)));
    out_.tracks[p.track].push_back(p.vertex);
  }

  // Skips slivers (twice the area must exceed 1e-6 of the longest edge squared) and triangles
  // across a tear.
  void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const glm::vec3 pa = out_.mesh.positions[a], pb = out_.mesh.positions[b], pc = out_.mesh.positions[c];
    const float area2 = glm::length(glm::cross(pb - pa, pc - pa));
    const float longest2 = std::max({glm::dot(pb - pa, pb - pa), glm::dot(pc - pb, pc - pb), glm::dot(pa - pc, pa - pc)});
    if (!(area2 > 1e-6f * longest2) || longest2 <= 0.0f || longest2 > tearLength2_) return;
    out_.mesh.triangles.push_back({a, b, c});
  }

 private:
  IntegralSurface& out_;
  float tearLength2_;
};

// Stitches the strip between the old front and the new one (both ordered by s, same end
// parameters): the next triangle advances on the front whose next particle has the smaller s;
// at equal s (the same particle one step later) the shorter diagonal wins (Hultquist).
void stitchStrip(const FrontRun& older, const FrontRun& newer, const IntegralSurface& surface, SurfaceAssembly& assembly) {
  std::size_t i = 0, j = 0;
  const auto& pos = surface.mesh.positions;
  while (i + 1 < older.size() || j + 1 < newer.size()) {
    bool advanceOld;
    if (i + 1 == older.size()) advanceOld = false;
    else if (j + 1 == newer.size()) advanceOld = true;
    else if (older[i + 1].s < newer[j + 1].s) advanceOld = true;
    else if (older[i + 1].s > newer[j + 1].s) advanceOld = false;
    else
      advanceOld = glm::distance(pos[older[i + 1].vertex], pos[newer[j].vertex]) <=
                   glm::distance(pos[older[i].vertex], pos[newer[j + 1].vertex]);
    if (advanceOld) {
      assembly.addTriangle(older[i].vertex, older[i + 1].vertex, newer[j].vertex);
      ++i;
    } else {
      assembly.addTriangle(older[i].vertex, newer[j + 1].vertex, newer[j].vertex);
      ++j;
    }
  }
}

// One advance of the whole front from tOld to tNew.
class FrontStep {
 public:
  FrontStep(const ParticleIntegrator& integrator, const AdvancingFrontSettings& settings, double tOld, double tNew,
            IntegralSurface& surface)
      : integrator_(integrator), settings_(settings), tOld_(tOld), tNew_(tNew), surface_(surface) {}

  std::vector<FrontRun> run(const std::vector<FrontRun>& runs, double tSinceSeed, FrontStatistics& stats) {
    SurfaceAssembly assembly(surface_, tearLength());
    std::vector<FrontRun> next;
    for (const auto& older : runs) {
      const FrontRun advanced = advanceRun(older);
      const FieldDomain domain = integrator_.field().domain();
      std::size_t a = 0;
      while (a < older.size()) {
        std::size_t b = a;
        while (b < older.size() && isValid(advanced[b].position, domain)) ++b;
        if (b - a >= 2) {
          const FrontRun oldPiece(older.begin() + std::ptrdiff_t(a), older.begin() + std::ptrdiff_t(b));
          FrontRun newPiece(advanced.begin() + std::ptrdiff_t(a), advanced.begin() + std::ptrdiff_t(b));
          newPiece = coarsen(refineByBend(refineBySpacing(newPiece, oldPiece, stats), oldPiece, stats), stats);
          for (auto& p : newPiece) assembly.addVertex(p, tSinceSeed);
          stitchStrip(oldPiece, newPiece, surface_, assembly);
          for (auto& piece : tearApart(newPiece)) next.push_back(std::move(piece));
        }
        a = b + 1;
      }
    }
    return next;
  }

 private:
  double tearLength() const { return settings_.tearFactor * settings_.maxSpacing; }

  // Splits the front where neighbours are farther apart than the tear length; drops single particles.
  std::vector<FrontRun> tearApart(const FrontRun& front) const {
    std::vector<FrontRun> pieces(1);
    for (std::size_t k = 0; k < front.size(); ++k) {
      if (k > 0 && glm::distance(front[k - 1].position, front[k].position) > tearLength()) pieces.emplace_back();
      pieces.back().push_back(front[k]);
    }
    std::erase_if(pieces, [](const FrontRun& r) { return r.size() < 2; });
    return pieces;
  }

  static bool isValid(const glm::dvec3& p, const FieldDomain& domain) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && domain.contains(p);
  }

  FrontRun advanceRun(const FrontRun& older) {
    FrontRun out = older;
    for (auto& p : out) p.position = advance(p.position);
    return out;
  }

  glm::dvec3 advance(const glm::dvec3& x) {
    const ParticleAdvance a = integrator_.advance(x, tOld_, tNew_);
    surface_.integratorSteps += a.steps;
    return a.position;
  }

  // A new particle at parameter s: seeded on the old front, integrated to the new time.
  FrontParticle insertAt(double s, const FrontRun& older) {
    FrontParticle p;
    p.s = s;
    p.position = advance(positionOnRun(older, s));
    return p;
  }

  bool canInsert(const FrontParticle& a, const FrontParticle& b, std::size_t count) const {
    return b.s - a.s > 2.0 * settings_.minParameterGap && count < settings_.maxParticles;
  }

  // Hultquist: split every gap wider than maxSpacing, recursively.
  FrontRun refineBySpacing(const FrontRun& front, const FrontRun& older, FrontStatistics& stats) {
    FrontRun out{front.front()};
    for (std::size_t k = 0; k + 1 < front.size(); ++k) {
      std::vector<FrontParticle> pending{front[k + 1]};  // stack of right ends still to reach
      while (!pending.empty()) {
        const FrontParticle& a = out.back();
        const FrontParticle b = pending.back();
        const std::size_t count = out.size() + pending.size() + (front.size() - k);
        if (glm::distance(a.position, b.position) > settings_.maxSpacing && canInsert(a, b, count)) {
          pending.push_back(insertAt(0.5 * (a.s + b.s), older));
          ++stats.inserted;
        } else {
          out.push_back(b);
          pending.pop_back();
        }
      }
    }
    return out;
  }

  // Garth: where the front turns by more than maxBend, split both neighbouring segments (when they
  // are long enough that the split does not fall below minSpacing).
  FrontRun refineByBend(const FrontRun& front, const FrontRun& older, FrontStatistics& stats) {
    std::vector<bool> split(front.size(), false);  // split[k]: segment (k, k+1)
    for (std::size_t k = 1; k + 1 < front.size(); ++k)
      if (bendDegrees(front[k - 1].position, front[k].position, front[k + 1].position) > settings_.maxBendDegrees) {
        split[k - 1] = true;
        split[k] = true;
      }
    FrontRun out{front.front()};
    for (std::size_t k = 0; k + 1 < front.size(); ++k) {
      const FrontParticle& a = front[k];
      const FrontParticle& b = front[k + 1];
      if (split[k] && glm::distance(a.position, b.position) > 2.0 * settings_.minSpacing && canInsert(a, b, out.size() + front.size())) {
        out.push_back(insertAt(0.5 * (a.s + b.s), older));
        ++stats.inserted;
      }
      out.push_back(b);
    }
    return out;
  }

  // Hultquist: remove interior particles that crowd their predecessor, unless that opens a gap
  // wider than maxSpacing or removes a sharp turn.
  FrontRun coarsen(const FrontRun& front, FrontStatistics& stats) const {
    FrontRun out{front.front()};
    for (std::size_t k = 1; k + 1 < front.size(); ++k) {
      const FrontParticle& prev = out.back();
      const bool crowded = glm::distance(prev.position, front[k].position) < settings_.minSpacing;
      const bool gapStaysSmall = glm::distance(prev.position, front[k + 1].position) <= settings_.maxSpacing;
      const bool flat = bendDegrees(prev.position, front[k].position, front[k + 1].position) <= settings_.maxBendDegrees;
      if (crowded && gapStaysSmall && flat) ++stats.removed;
      else out.push_back(front[k]);
    }
    out.push_back(front.back());
    return out;
  }

  const ParticleIntegrator& integrator_;
  const AdvancingFrontSettings& settings_;
  double tOld_, tNew_;
  IntegralSurface& surface_;
};

void measureFront(const std::vector<FrontRun>& runs, FrontStatistics& stats) {
  stats.runs = runs.size();
  stats.particles = 0;
  stats.minSpacing = std::numeric_limits<double>::infinity();
  stats.maxSpacing = 0.0;
  for (const auto& run : runs) {
    stats.particles += run.size();
    for (std::size_t k = 0; k + 1 < run.size(); ++k) {
      const double d = glm::distance(run[k].position, run[k + 1].position);
      stats.minSpacing = std::min(stats.minSpacing, d);
      stats.maxSpacing = std::max(stats.maxSpacing, d);
    }
  }
}

}  // namespace

IntegralSurface AdvancingFront::sweep(const SeedCurve& seed, double t0) const {
  IntegralSurface surface;
  SurfaceAssembly assembly(surface, settings_.tearFactor * settings_.maxSpacing);
  // The seed front: uniform in s, then refined like any other front (its "old front" is itself).
  const int initial = std::max(2, int(std::ceil(seed.length() / settings_.maxSpacing)) + 1);
  FrontRun seedFront;
  for (int i = 0; i < initial; ++i) {
    FrontParticle p;
    p.s = double(i) / double(initial - 1);
    p.position = seed.at(p.s);
    seedFront.push_back(p);
  }
  for (auto& p : seedFront) assembly.addVertex(p, 0.0);
  std::vector<FrontRun> runs{seedFront};
  FrontStatistics seedStats;
  measureFront(runs, seedStats);
  surface.fronts.push_back(seedStats);
  for (int step = 1; step <= settings_.steps && !runs.empty(); ++step) {
    const double tOld = t0 + settings_.timeStep * (step - 1), tNew = t0 + settings_.timeStep * step;
    FrontStatistics stats;
    stats.step = step;
    FrontStep frontStep(integrator_, settings_, tOld, tNew, surface);
    runs = frontStep.run(runs, tNew - t0, stats);
    measureFront(runs, stats);
    surface.fronts.push_back(stats);
  }
  render::computeVertexNormals(surface.mesh);
  return surface;
}

IntegralSurface streamSurface(const VectorField& field, const SeedCurve& seed, double t0, const IntegratorSettings& integrator,
                              const AdvancingFrontSettings& front) {
  const FrozenTimeField frozen(field, t0);
  const ParticleIntegrator particles(frozen, integrator);
  return AdvancingFront(particles, front).sweep(seed, t0);
}

IntegralSurface pathSurface(const VectorField& field, const SeedCurve& seed, double t0, const IntegratorSettings& integrator,
                            const AdvancingFrontSettings& front) {
  const ParticleIntegrator particles(field, integrator);
  return AdvancingFront(particles, front).sweep(seed, t0);
}

}  // namespace tlab::stimuli
