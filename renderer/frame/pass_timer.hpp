#pragma once
// Wall-clock time per render pass. Each pass ends with glFinish when timing is on, so the time is
// the pass's own (llvmpipe executes GL work on the CPU; a GPU would need timer queries instead).
// Within a pass, its parts (a dispatch, a group of them, a read-back) may be timed too, when asked
// for (RenderRequest::timeParts, `tlab bench render --scene ... --parts`).
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

  // A part of the pass that is running, timed on its own when parts are timed (else just run):
  // with a glFinish before and after it when timing is on, so the part's time is its own and the
  // pass's time includes those waits. Times and counts of a repeated name add up.
  struct Part {
    std::string name;
    double ms = 0;
    int count = 0;  // how many times it ran in the frame (e.g. the solve's steps)
  };
  void timeParts(bool on) { partsOn_ = on; }
  template <typename F>
  void part(const std::string& name, F&& work) {
    if (!partsOn_) {
      work();
      return;
    }
    if (enabled_) finish();
    const auto start = std::chrono::steady_clock::now();
    work();
    if (enabled_) finish();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    for (auto& p : parts_)
      if (p.name == name) {
        p.ms += ms;
        ++p.count;
        return;
      }
    parts_.push_back(Part{name, ms, 1});
  }
  const std::vector<Part>& parts() const { return parts_; }
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
  bool partsOn_ = false;
  std::string lastPass_;
  std::vector<std::pair<std::string, double>> passes_;
  std::vector<Part> parts_;
};

// `work` as a part of the running pass where a timer is given (passes called from tests and tools
// may have none), else just run.
template <typename F>
void timePart(PassTimer* timer, const std::string& name, F&& work) {
  if (timer) timer->part(name, std::forward<F>(work));
  else work();
}

}  // namespace tlab::render
