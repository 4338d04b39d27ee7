#pragma once
// A thread that owns a GL context (the RenderWorker's, each LiveRenderer's): startGlThread makes
// the context on a new thread, runs `setUp` with it there and waits for both (their error is
// rethrown here), then leaves the thread to `serve` until it returns (the context goes after it);
// stopGlThread raises the owner's stop flag under its mutex, wakes it and joins it.
#include <condition_variable>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>

#include "renderer/gpu/gpu_context.hpp"

namespace tlab::study {

inline std::thread startGlThread(std::function<void(const gpu::GpuContext&)> setUp, std::function<void()> serve) {
  std::promise<void> ready;
  auto started = ready.get_future();
  std::thread thread([&ready, setUp = std::move(setUp), serve = std::move(serve)] {
    std::unique_ptr<gpu::GpuContext> context;
    try {
      context = gpu::createHeadlessContext();
      setUp(*context);
      ready.set_value();  // `ready` is not touched after this: startGlThread returns
    } catch (...) {
      ready.set_exception(std::current_exception());
      return;
    }
    serve();
  });
  try {
    started.get();  // the context's error, if it could not be made
  } catch (...) {
    thread.join();
    throw;
  }
  return thread;
}

inline void stopGlThread(std::mutex& mutex, bool& stopping, std::condition_variable& wake, std::thread& thread) {
  {
    std::lock_guard lock(mutex);
    stopping = true;
  }
  wake.notify_all();
  thread.join();
}

}  // namespace tlab::study
