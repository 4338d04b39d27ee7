#pragma once
// Wall-clock time per render pass. Each pass ends with glFinish when timing is on, so the time is
// the pass's own (llvmpipe executes GL work on the CPU; a GPU would need timer queries instead).
#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace tlab::render {

class PassTimer {
 public:
  explicit PassTimer(bool enabled = true) : enabled_(enabled) {}
  // For benchmarks that count a frame's work pass by pass (tlab bench render --until): the passes
  // after `name` has run are skipped (further runs of `name` itself are not), so the frame ends
  // there. Empty: every pass runs.
  void stopAfter(std::string name) { lastPass_ = std::move(name); }
  bool ran(const std::string& name) const {
    for (const auto& p : passes_)
      if (p.first == name) return true;
    return false;
  }
  // Runs `pass`, records its time under `name` (times of a repeated name add up), returns it.
  template <typename F>
  void time(const std::string& name, F&& pass) {
    if (!lastPass_.empty() && name != lastPass_ && ran(lastPass_)) return;
    const auto start = std::chrono::steady_clock::now();
    pass();
    if (enabled_) finish();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    for (auto& [n, t] : passes_)
      if (n == name) {
        t += ms;
        return;
      }
    passes_.emplace_back(name, ms);
  }
  const std::vector<std::pair<std::string, double>>& passes() const { return passes_; }
  double total() const {
    double t = 0;
    for (const auto& p : passes_) t += p.second;
    return t;
  }
  double get(const std::string& name) const {
    for (const auto& [n, t] : passes_)
      if (n == name) return t;
    return 0.0;
  }

 private:
  static void finish();
  bool enabled_;
  std::string lastPass_;
  std::vector<std::pair<std::string, double>> passes_;
};

}  // namespace tlab::render
