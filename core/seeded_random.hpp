#pragma once
// A seeded random source whose output is identical on every platform and standard library:
// std::mt19937 is fully specified, the std:: distributions are not, so we map bits ourselves.
#include <cstdint>
#include <random>

#include <glm/vec3.hpp>

namespace tlab::core {

class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : engine_(static_cast<std::uint32_t>(seed ^ (seed >> 32))) {}
  std::uint32_t bits() { return engine_(); }
  // Uniform in [0, 1) with 24 bits of resolution.
  float uniform() { return static_cast<float>(engine_() >> 8) * (1.0f / 16777216.0f); }
  float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
  // A point with each coordinate uniform in [lo, hi), drawn z first, then y, then x: the order in
  // which the first builds (GCC, a call's arguments last to first) drew the points of the flow
  // surfaces' seed lines and the abstract worlds, kept so that those stay byte-identical.
  glm::vec3 pointZFirst(float lo, float hi) {
    const float z = uniform(lo, hi);
    const float y = uniform(lo, hi);
    const float x = uniform(lo, hi);
    return {x, y, z};
  }
  // Uniform integer in [0, n) (n > 0), by rejection: no modulo bias.
  std::uint32_t below(std::uint32_t n) {
    const std::uint32_t limit = UINT32_MAX - UINT32_MAX % n;
    std::uint32_t r;
    do r = engine_();
    while (r >= limit);
    return r % n;
  }

 private:
  std::mt19937 engine_;
};

}  // namespace tlab::core
