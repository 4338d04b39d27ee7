#include "study/serve/load_client.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace tlab::study {

Percentiles percentiles(std::vector<double> values) {
  Percentiles p;
  p.count = values.size();
  if (values.empty()) return p;
  std::sort(values.begin(), values.end());
  const auto rank = [&values](double q) { return values[std::size_t(std::max(0.0, std::ceil(q * double(values.size())) - 1.0))]; };
  p.p50 = rank(0.50);
  p.p95 = rank(0.95);
  p.p99 = rank(0.99);
  p.max = values.back();
  return p;
}

std::string loadParticipantId(const std::string& prefix, int i) {
  char number[16];
  std::snprintf(number, sizeof number, "%03d", i + 1);
  return prefix + number;
}

LoadResult runLoad(const LoadOptions& o) {
  if (o.participants < 1 || o.concurrency < 1) throw std::invalid_argument("loadtest: --participants and --concurrency must be at least 1");
  const LoadTarget target = parseLoadTarget(o.url, o.parameter);
  std::vector<ParticipantRun> runs(std::size_t(o.participants));
  std::atomic<int> next{0}, acknowledged{0};
  std::mutex ackMutex;  // onAck calls come one at a time: a test may stop the server inside one
  const auto onAck = [&](const AckedTrial& t) {
    const int n = ++acknowledged;
    if (!o.onAck) return;
    std::lock_guard lock(ackMutex);
    o.onAck(n, t);
  };
  const auto start = std::chrono::steady_clock::now();
  {
    std::vector<std::thread> threads;
    for (int c = 0; c < std::min(o.concurrency, o.participants); ++c)
      threads.emplace_back([&] {
        for (int i = next++; i < o.participants; i = next++) {
          // Seeded per participant: the same participant thinks and answers alike whatever thread runs it.
          LoadParticipant p(target, loadParticipantId(o.pidPrefix, i), o.seed * 1000003ULL + std::uint64_t(i), o.behaviour, onAck);
          runs[std::size_t(i)] = p.walk();
        }
      });
    for (auto& t : threads) t.join();
  }
  LoadResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<double> ack, requests, starts, frames, firstFrames;
  std::vector<std::pair<std::string, std::vector<double>>> stages;
  for (const auto& run : runs) {
    (run.finished ? r.finished : r.failed) += 1;
    if (!run.finished && r.firstError.empty()) r.firstError = run.error;
    r.reconnects += run.reconnects;
    r.acked.insert(r.acked.end(), run.acked.begin(), run.acked.end());
    ack.insert(ack.end(), run.ackMs.begin(), run.ackMs.end());
    requests.insert(requests.end(), run.requestMs.begin(), run.requestMs.end());
    starts.insert(starts.end(), run.startMs.begin(), run.startMs.end());
    frames.insert(frames.end(), run.frameMs.begin(), run.frameMs.end());
    firstFrames.insert(firstFrames.end(), run.firstFrameMs.begin(), run.firstFrameMs.end());
    for (const auto& [name, ms] : run.stageMs) {
      auto at = std::find_if(stages.begin(), stages.end(), [&name = name](const auto& s) { return s.first == name; });
      if (at == stages.end()) at = stages.insert(stages.end(), {name, {}});
      at->second.insert(at->second.end(), ms.begin(), ms.end());
    }
    if (run.liveSeconds > 0.0) r.framesPerSecond.push_back(double(run.frameMs.size()) / run.liveSeconds);
  }
  r.acknowledged = int(r.acked.size());
  r.ack = percentiles(std::move(ack));
  r.requests = percentiles(std::move(requests));
  r.start = percentiles(std::move(starts));
  r.frame = percentiles(std::move(frames));
  r.firstFrame = percentiles(std::move(firstFrames));
  for (auto& [name, ms] : stages) r.stages.emplace_back(name, percentiles(std::move(ms)));
  return r;
}

}  // namespace tlab::study
