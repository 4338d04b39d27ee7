#pragma once
// Steady-state frame timing for the benchmarks: one warm-up frame (shader compilation, pool
// growth), then the median per pass and per frame over N timed frames.
#include <string>
#include <utility>
#include <vector>

#include "renderer/pipeline/renderer.hpp"

namespace tlab::app {

struct FrameTiming {
  std::vector<std::pair<std::string, double>> passes;  // median ms per pass, in the order they ran
  double frameMs = 0;                                   // median of the per-frame sums
  std::uint64_t fragments = 0;
  std::vector<std::string> operations;
};

double median(std::vector<double> v);
FrameTiming timeFrames(render::Renderer& renderer, const render::RenderRequest& request, int frames);
double passSum(const std::vector<std::pair<std::string, double>>& passes);

}  // namespace tlab::app
