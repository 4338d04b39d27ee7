#include "app/frame_timing.hpp"

#include <algorithm>

namespace tlab::app {

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
  for (int i = 0; i < frames; ++i) {
    r.render(q, &stats);
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
  return t;
}

}  // namespace tlab::app
