#pragma once
// Steady-state frame timing for the benchmarks (`tlab bench`): one warm-up frame (shader
// compilation, pool growth), then medians over N timed frames — per pass from the Renderer's pass
// timer, or per whole frame by the wall clock (each frame ends with the image read back, so the
// GPU work is in it).
#include <string>
#include <utility>
#include <vector>

#include "renderer/pipeline/renderer.hpp"

namespace tlab::bench {

struct FrameTiming {
  std::vector<std::pair<std::string, double>> passes;  // median ms per pass, in the order they ran
  double frameMs = 0;                                   // median of the per-frame sums
  std::uint64_t fragments = 0;
  std::vector<std::string> operations;
  // With RenderRequest::timeParts: each part's median ms per frame (of its frame's sum) and how many
  // times it ran in the last frame, in the order the parts first ran.
  std::vector<render::PassTimer::Part> parts;
};

double median(std::vector<double> v);
FrameTiming timeFrames(render::Renderer& renderer, const render::RenderRequest& request, int frames);
double passSum(const std::vector<std::pair<std::string, double>>& passes);

struct OrbitTiming {
  double medianMs = 0, meanMs = 0;
  std::uint64_t fragments = 0;
  std::vector<std::pair<std::string, double>> passes;  // of the last frame
};
// Wall-clock time of one frame per camera of `orbit` after one warm-up frame; frame i uses camera i.
OrbitTiming timeOrbit(render::Renderer& renderer, render::RenderRequest request, const std::vector<render::Camera>& orbit);

}  // namespace tlab::bench
