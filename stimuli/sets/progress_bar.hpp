#pragma once
// A one-line progress bar on stderr, drawn only when stderr is a terminal (never in pipes, logs
// or tests). Thread-safe: workers call advance().
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace tlab::stimuli {

class ProgressBar {
 public:
  // `enabled` = false never draws (e.g. --quiet).
  ProgressBar(std::string title, std::size_t total, bool enabled = true);
  ~ProgressBar();
  void advance(std::size_t done = 1);
  bool visible() const { return visible_; }

 private:
  void draw();
  std::string title_;
  std::size_t total_, done_ = 0;
  bool visible_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace tlab::stimuli
