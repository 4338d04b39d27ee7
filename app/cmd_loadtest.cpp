// tlab loadtest URL --participants N --concurrency C: N simulated participants walk whole
// sessions of a running `tlab serve` over HTTP, at most C at a time (study/serve/load_client.hpp),
// and the server's figures are printed: participants finished and failed, responses
// acknowledged, throughput, and the latency percentiles from an answer to its acknowledgement
// and of every request. Exit code 1 when a participant failed, with the first error.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "app/commands.hpp"
#include "study/serve/load_client.hpp"

namespace tlab::app {

namespace {

void printLatency(const char* what, const study::Percentiles& p) {
  std::printf("%s (ms, n=%zu): p50 %.1f  p95 %.1f  p99 %.1f  max %.1f\n", what, p.count, p.p50, p.p95, p.p99, p.max);
}

void loadtest(const study::LoadOptions& o) {
  const study::LoadResult r = study::runLoad(o);
  std::printf("participants: %d finished, %d failed (of %d, %d at a time)\n", r.finished, r.failed, o.participants, o.concurrency);
  std::printf("responses acknowledged: %d in %.1f s: %.1f responses/s\n", r.acknowledged, r.seconds, r.throughput());
  printLatency("answer -> acknowledgement", r.ack);
  printLatency("all requests", r.requests);
  printLatency("display report -> first screen", r.start);
  if (r.frame.count > 0) {  // live trials: frames a second of each participant while exploring, and input → frame
    std::vector<double> fps = r.framesPerSecond;
    std::sort(fps.begin(), fps.end());
    std::printf("live frames: %zu; frames/s per participant: min %.1f  median %.1f  max %.1f\n", r.frame.count, fps.front(), fps[fps.size() / 2],
                fps.back());
    printLatency("live input -> frame", r.frame);
    printLatency("live first frame of a trial", r.firstFrame);
    std::printf("live frame on the server (ms, p50/p95):");  // Server-Timing's stages, in the server's order
    for (const auto& [name, p] : r.stages) std::printf("  %s %.2f/%.2f", name.c_str(), p.p50, p.p95);
    std::printf("\n");
  }
  if (r.reconnects > 0) std::printf("reconnections: %d\n", r.reconnects);
  std::fflush(stdout);
  if (r.failed > 0) throw std::runtime_error(r.firstError);
}

}  // namespace

void addLoadtestCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("loadtest", "Simulated participants walk whole sessions of a running `tlab serve` (capacity test)");
  auto o = std::make_shared<study::LoadOptions>();
  cmd->add_option("url", o->url, "the participants' link without the id: http://HOST:PORT/s/EXPERIMENT")->required();
  cmd->add_option("--participants", o->participants, "simulated participants")->capture_default_str()->check(CLI::Range(1, 1000000));
  cmd->add_option("--concurrency", o->concurrency, "participants at a time (one thread each)")->capture_default_str()->check(CLI::Range(1, 10000));
  cmd->add_option("--think", o->behaviour.thinkMs, "mean think time before each answer or button press, ms (exponential)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 3600000.0));
  cmd->add_option("--live-seconds", o->behaviour.liveSeconds,
                  "live trials (orbit, walk): explore each this long, input sent as fast as frames come back (0: the think time)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 3600.0));
  cmd->add_option("--seed", o->seed, "seed of the think times and answers")->capture_default_str();
  cmd->add_option("--pid-prefix", o->pidPrefix, "participant ids: PREFIX001, PREFIX002, ...")->capture_default_str();
  cmd->add_option("--param", o->parameter, "the link's participant parameter (the experiment's [online] participant_parameter)")
      ->capture_default_str();
  cmd->add_option("--retry-seconds", o->behaviour.retrySeconds,
                  "how long a participant keeps retrying through one outage (lost connection, server restart), as the page does")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 86400.0));
  cmd->callback([o] { loadtest(*o); });
}

}  // namespace tlab::app
