#pragma once
// tlab loadtest: N simulated participants (LoadParticipant) walk whole sessions of `tlab serve`
// over HTTP, at most C at a time, one thread each. The result holds what a capacity plan needs —
// how many finished, how many responses the server acknowledged, throughput and latencies — and
// which trials were acknowledged, so a test can check each of them was stored exactly once.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "study/serve/load_participant.hpp"

namespace tlab::study {

struct LoadOptions {
  std::string url;  // the participants' link base: http://HOST:PORT/s/EXPERIMENT
  std::string parameter = "pid";
  int participants = 1;
  int concurrency = 1;
  LoadBehaviour behaviour;
  std::uint64_t seed = 1;
  std::string pidPrefix = "load-";
  // Called from the participants' threads after each acknowledged answer, with the count so far.
  std::function<void(int acknowledged, const AckedTrial&)> onAck;
};

struct Percentiles {
  std::size_t count = 0;
  double p50 = 0, p95 = 0, p99 = 0, max = 0;
};

// Nearest-rank percentiles of `values` (milliseconds); all zero when empty.
Percentiles percentiles(std::vector<double> values);

struct LoadResult {
  int finished = 0, failed = 0;
  int acknowledged = 0;
  int reconnects = 0;
  double seconds = 0.0;  // wall time of the whole run
  Percentiles ack, requests, start;  // answer → acknowledgement; every request; display report → first screen
  Percentiles frame;                 // live trials: input → frame
  Percentiles firstFrame;            // live trials: a trial's start view (its renderer may be built for it)
  std::vector<std::pair<std::string, Percentiles>> stages;  // live trials: each stage of a frame on the server
  std::vector<double> framesPerSecond;  // live trials: each participant's frames a second while exploring
  std::vector<AckedTrial> acked;  // every acknowledged trial, by participant
  std::string firstError;         // the first failed participant's error line
  double throughput() const { return seconds > 0.0 ? acknowledged / seconds : 0.0; }
};

// The participant id of simulated participant `i` (0-based): prefix + 3-digit number from 1.
std::string loadParticipantId(const std::string& prefix, int i);

// Runs the load; throws std::invalid_argument for a malformed URL or counts.
LoadResult runLoad(const LoadOptions& options);

}  // namespace tlab::study
