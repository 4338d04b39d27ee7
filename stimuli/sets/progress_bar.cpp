#include "stimuli/sets/progress_bar.hpp"

#include <unistd.h>

#include <cstdio>

namespace tlab::stimuli {

ProgressBar::ProgressBar(std::string title, std::size_t total, bool enabled)
    : title_(std::move(title)), total_(total), visible_(enabled && ::isatty(STDERR_FILENO) == 1), start_(std::chrono::steady_clock::now()) {
  if (visible_) draw();
}

ProgressBar::~ProgressBar() {
  if (visible_) std::fputc('\n', stderr);
}

void ProgressBar::advance(std::size_t done) {
  const std::lock_guard lock(mutex_);
  done_ += done;
  if (visible_) draw();
}

void ProgressBar::draw() {
  constexpr int width = 30;
  const double fraction = total_ ? double(done_) / double(total_) : 1.0;
  const int filled = int(fraction * width + 0.5);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "\r%s [%.*s%*s] %zu/%zu %.1fs", title_.c_str(), filled, "##############################", width - filled, "", done_,
               total_, seconds);
  std::fflush(stderr);
}

}  // namespace tlab::stimuli
