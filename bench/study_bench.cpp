// Study benchmarks: building designs and session plans, the cost of the crash-safe write path
// (one SQLite transaction per response, synchronous=FULL, WAL), and the SHA-256 of a live frame's
// pixels that the window logs once per picture shown (tlab replay checks it). End-to-end simulated trials per
// second (rendering, probing, observer, scoring, storing) are measured with
// `tlab simulate ... --participants N --db sim.db`, which prints trials/s.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "study/design/counterbalancing.hpp"
#include "study/design/experiment_file.hpp"
#include "study/design/graeco_latin_square.hpp"
#include "study/design/session_plan.hpp"
#include "study/store/open_store.hpp"
#include "study/design/williams_design.hpp"
#include "study/run/frame_log.hpp"

using namespace tlab::study;

namespace {

// The design of examples/elmqvist.toml (2 × 2 within, Latin square, 4 tasks × 3 trials, 16 participants).
Experiment elmqvistDesign() {
  return parseExperiment(R"(
id = "elmqvist-bench"
participants = 16
counterbalancing = "latin-square"
[[factors]]
name = "transparency"
levels = [{ name = "inactive", style = "opaque" }, { name = "active", style = "dynamic" }]
[[factors]]
name = "scenario"
levels = [{ name = "abstract", scene = "builtin:abstract?seed={trial}" }, { name = "walkthrough", scene = "builtin:walkthrough?seed=5" }]
[[tasks]]
id = "T1"
task = "counting"
when = { scenario = "abstract" }
trials = 3
[[tasks]]
id = "T2"
task = "pattern"
when = { scenario = "abstract" }
trials = 3
[[tasks]]
id = "T3"
task = "target-discovery"
when = { scenario = "walkthrough" }
trials = 3
[[tasks]]
id = "T4"
task = "counting"
when = { scenario = "walkthrough" }
trials = 3
)", "elmqvist-bench.toml");
}

}  // namespace

static void BM_WilliamsDesign(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(williamsDesign(int(state.range(0))));
}
BENCHMARK(BM_WilliamsDesign)->Arg(4)->Arg(9)->Arg(16);

static void BM_GraecoLatinSquare(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(graecoLatinSquare(int(state.range(0))));
}
BENCHMARK(BM_GraecoLatinSquare)->Arg(3)->Arg(8)->Arg(9);

static void BM_ElmqvistSessionPlans(benchmark::State& state) {
  const Experiment e = elmqvistDesign();
  const Design design = makeDesign(e);
  for (auto _ : state)
    for (int slot = 0; slot < e.participants; ++slot) benchmark::DoNotOptimize(makeSessionPlan(e, design, slot));
  state.SetItemsProcessed(state.iterations() * 384);
}
BENCHMARK(BM_ElmqvistSessionPlans);

// One committed transaction per response: the write path a participant waits for between trials.
static void BM_RecordResponse(benchmark::State& state) {
  const auto path = std::filesystem::temp_directory_path() / ("tlab_bench_store_" + std::to_string(::getpid()) + ".db");
  std::filesystem::remove(path);
  const Experiment e = elmqvistDesign();
  {
    const auto storeOwner = openStore(path.string());
    Store& store = *storeOwner;
    const int n = 200000;
    std::vector<TrialRecord> trials(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      trials[std::size_t(i)].sequence = i + 1;
      trials[std::size_t(i)].phase = "test";
    }
    const auto p = *store.enrol(e, "bench", "bench", 0, makeDesign(e), trials);
    const auto stored = store.trials(p.id);
    const auto session = store.startSession(p.id, e, "bench", "bench");
    std::size_t next = 0;
    for (auto _ : state) {
      ResponseRecord r;
      r.trial = stored[next++ % stored.size()].id;
      r.session = session;
      r.rawAnswer = "42";
      r.answered = true;
      store.recordResponse(r);
    }
    state.SetItemsProcessed(state.iterations());
  }
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path.string() + suffix);
}
BENCHMARK(BM_RecordResponse)->Iterations(2000);


// The frame log's hash of one live picture of N×N pixels (RGBA, as the window and browser log it).
// A live trial's frame events stored after the trial: one commit each (recordEvent) against one
// transaction for all (recordEvents, what the trial runner does). Arg: the frames of the trial.
static void storeFrameEvents(benchmark::State& state, bool batched) {
  const auto path = std::filesystem::temp_directory_path() / ("tlab_bench_events_" + std::to_string(::getpid()) + ".db");
  std::filesystem::remove(path);
  const Experiment e = elmqvistDesign();
  {
    const auto storeOwner = openStore(path.string());
    Store& store = *storeOwner;
    std::vector<TrialRecord> trials(1);
    trials[0].phase = "test";
    const auto p = *store.enrol(e, "bench", "bench", 0, makeDesign(e), trials);
    const auto trial = store.trials(p.id).at(0).id;
    const auto session = store.startSession(p.id, e, "bench", "bench");
    std::vector<EventRecord> frames(static_cast<std::size_t>(state.range(0)));
    for (std::size_t i = 0; i < frames.size(); ++i)
      frames[i] = {std::int64_t(i), "frame", R"({"index":)" + std::to_string(i) + R"(,"camera":"eye=1,2,3 target=0,0,0","sha256":")" + std::string(64, 'a') + "\"}"};
    for (auto _ : state) {
      if (batched) store.recordEvents(session, trial, frames);
      else
        for (const auto& f : frames) store.recordEvent(session, trial, f.tNs, f.kind, f.detail);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
  }
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path.string() + suffix);
}
static void BM_FrameEventsOneCommitEach(benchmark::State& state) { storeFrameEvents(state, false); }
static void BM_FrameEventsOneTransaction(benchmark::State& state) { storeFrameEvents(state, true); }
BENCHMARK(BM_FrameEventsOneCommitEach)->Arg(300)->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FrameEventsOneTransaction)->Arg(300)->Iterations(3)->Unit(benchmark::kMillisecond);

static void BM_FramePixelsSha256(benchmark::State& state) {
  const int n = int(state.range(0));
  Canvas frame(n, n, {40, 90, 160, 255});
  for (int i = 0; i < n; ++i) frame.fillRect({i, i, 1, 1}, {255, 255, 255, 255});
  for (auto _ : state) benchmark::DoNotOptimize(framePixelsSha256(frame));
  state.SetBytesProcessed(state.iterations() * std::int64_t(n) * n * 4);
}
BENCHMARK(BM_FramePixelsSha256)->Arg(160)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond);
