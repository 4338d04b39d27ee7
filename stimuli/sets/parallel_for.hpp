#pragma once
// The worker pool of a stimulus set: units run on several threads, each with its own state (a GL
// context), and their results land in fixed slots, so the output never depends on `jobs`.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace tlab::stimuli {

// Runs body(i) for i in [0, count) on `jobs` threads (the caller's thread is one of them), each
// thread first calling setUp() for its own state. The first exception stops the others and is
// rethrown. Results must be written to per-index slots: the order of execution never matters.
template <class SetUp, class Body>
void parallelFor(std::size_t count, int jobs, SetUp setUp, Body body) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex failureMutex;
  std::exception_ptr failure;
  const auto work = [&] {
    try {
      auto state = setUp();
      for (std::size_t i = next++; i < count && !stop; i = next++) body(i, state);
    } catch (...) {
      const std::lock_guard lock(failureMutex);
      if (!failure) failure = std::current_exception();
      stop = true;
    }
  };
  const int workers = std::max(1, std::min<int>(jobs, int(count)));
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w) threads.emplace_back(work);
  work();
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace tlab::stimuli
