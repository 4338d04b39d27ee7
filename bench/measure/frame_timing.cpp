#include "bench/measure/frame_timing.hpp"

#include <algorithm>
#include <chrono>

#include "renderer/gpu/gl.hpp"

namespace tlab::bench {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

double passSum(const std::vector<std::pair<std::string, double>>& passes) {
  double t = 0;
  for (const auto& p : passes) t += p.second;
  return t;
}

FrameTiming timeFrames(render::Renderer& r, const render::RenderRequest& q, int frames) {
  render::RenderStats stats;
  r.render(q, &stats);  // warm-up: shader compilation, pool growth
  std::vector<std::vector<double>> samples;
  std::vector<std::string> names;
  std::vector<double> totals;
  std::vector<render::PassTimer::Part> parts;  // in first-run order, with the last frame's counts
  std::vector<std::vector<double>> partSamples;  // each part's ms, a sample per frame it ran in
  for (int i = 0; i < frames; ++i) {
    r.render(q, &stats);
    for (const auto& part : stats.parts) {
      auto kept = std::find_if(parts.begin(), parts.end(), [&](const auto& p) { return p.name == part.name; });
      if (kept == parts.end()) {
        partSamples.emplace_back();
        kept = parts.insert(parts.end(), part);
      }
      kept->count = part.count;
      partSamples[std::size_t(kept - parts.begin())].push_back(part.ms);
    }
    for (std::size_t p = 0; p < stats.passMilliseconds.size(); ++p) {
      if (samples.size() <= p) {
        samples.emplace_back();
        names.push_back(stats.passMilliseconds[p].first);
      }
      samples[p].push_back(stats.passMilliseconds[p].second);
    }
    totals.push_back(passSum(stats.passMilliseconds));
  }
  FrameTiming t;
  t.fragments = stats.fragments;
  t.operations = stats.operations;
  for (std::size_t p = 0; p < names.size(); ++p) t.passes.emplace_back(names[p], median(samples[p]));
  t.frameMs = median(totals);
  for (std::size_t k = 0; k < parts.size(); ++k) parts[k].ms = median(partSamples[k]);
  t.parts = std::move(parts);
  return t;
}

OrbitTiming timeOrbit(render::Renderer& renderer, render::RenderRequest request, const std::vector<render::Camera>& orbit) {
  render::RenderStats stats;
  request.camera = orbit.front();
  renderer.render(request, &stats);  // warm-up: shader compilation, pool growth
  std::vector<double> ms;
  for (const auto& camera : orbit) {
    request.camera = camera;
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    renderer.render(request, &stats);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  OrbitTiming t;
  for (double m : ms) t.meanMs += m / double(ms.size());
  std::sort(ms.begin(), ms.end());
  t.medianMs = ms[ms.size() / 2];
  t.fragments = stats.fragments;
  t.passes = stats.passMilliseconds;
  return t;
}

}  // namespace tlab::bench
