#pragma once
// Timing one GL job for the benchmarks: glFinish before and after, so the time is the job's own
// GPU work (llvmpipe runs it on the CPU; a GPU would need timer queries instead).
#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

#include "renderer/gpu/gl.hpp"

namespace tlab::bench {

// Wall-clock and process CPU milliseconds of one GL job. The CPU time counts llvmpipe's worker
// threads too, so it is the robust figure on a shared machine.
struct GlTiming {
  double wallMs = 0, cpuMs = 0;
};
template <typename F>
GlTiming timeGlJob(F&& job) {
  glFinish();
  const auto wall = std::chrono::steady_clock::now();
  const std::clock_t cpu = std::clock();
  job();
  glFinish();
  return {std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall).count(),
          1000.0 * double(std::clock() - cpu) / CLOCKS_PER_SEC};
}

// Median wall-clock milliseconds of `repeats` frames after one warm-up frame (each frame ends
// with a read-back, so the GPU work is included).
template <typename F>
double medianFrameMs(int repeats, F&& frame) {
  frame();
  std::vector<double> t;
  for (int i = 0; i < repeats; ++i) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    frame();
    t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

}  // namespace tlab::bench
