#pragma once
// A thread that owns a GL context (the RenderWorker's, each LiveRenderer's): startGlThread runs
// `run` on a new thread and waits until it has made its context (`ready` set, or its error set and
// rethrown here); stopGlThread raises the owner's stop flag under its mutex, wakes it and joins it.
#include <condition_variable>
#include <functional>
#include <future>
#include <mutex>
#include <thread>

namespace tlab::study {

inline std::thread startGlThread(std::function<void(std::promise<void>& ready)> run) {
  std::promise<void> ready;
  auto started = ready.get_future();
  std::thread thread([&ready, run = std::move(run)] { run(ready); });
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
