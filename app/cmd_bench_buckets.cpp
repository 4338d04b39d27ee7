// tlab bench buckets: the synthetic benchmark of seed 002 (Murray et al., Sec. 6, Fig. 10):
// `quad-stack` with 32 full-screen quads at random depths, 512x512 (about 8.4 M fragments),
// the quads spread over 1, 2, 4, 8, 16, 32 objects (shapes). Per object count: the time of the
// neighbour query with buckets and by brute force (every fragment of the adjacent pixel,
// filtered by shape, as in the illustration buffer) on the same filled buffer, the k-buffer
// passes, and a whole plain k-buffer frame with constant opacity as the floor. Target: buckets >= 5x faster at >= 16 objects.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/scene_options.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "bench/measure/bucket_measurement.hpp"
#include "renderer/kbuffer/bucketed_kbuffer.hpp"

namespace tlab::app {

namespace {

struct BucketBenchOptions {
  std::string size = "512x512";
  int layers = 32;
  int k = 32;
  std::vector<int> objects = {1, 2, 4, 8, 16, 32};
  int repeats = 3;
  bool json = false;
};

void runBucketBench(const BucketBenchOptions& o) {
  const auto context = gpu::createHeadlessContext();
  const auto [width, height] = parseSize(o.size);
  // Bytes per fragment slot: Z + B + D (+ links + κ) with buckets; Z + D (+ links + κ) without B.
  const std::size_t bucketBytes = 4 + 4 + 8 + render::BucketedKBuffer::kLinkBytesPerSlot;
  const std::size_t bruteBytes = 4 + 8 + render::BucketedKBuffer::kLinkBytesPerSlot;
  nlohmann::json rows = nlohmann::json::array();
  if (!o.json) {
    std::printf("tlab bench buckets: quad-stack n=%d, %dx%d, k=%d, median of %d runs; ms wall (cpu = process CPU ms, "
                "llvmpipe threads included); target buckets >= 5x faster than brute force at >= 16 objects\n",
                o.layers, width, height, o.k, o.repeats);
    std::printf("memory per fragment: buckets %zu B (Z 4 + B 4 + D 8 + links 4 + kappa 4), brute force %zu B (no B); "
                "plain k-buffer 12 B (Z 4 + D 8)\n",
                bucketBytes, bruteBytes);
    std::printf("%7s %9s %8s %7s %7s %9s %9s %9s %9s %7s %7s %9s %10s\n", "objects", "fragments", "z-insert", "buckets",
                "data", "nbr_bkt", "nbr_brute", "cpu_bkt", "cpu_brute", "x_wall", "x_cpu", "curvature", "plain_kbuf");
  }
  for (int m : o.objects) {
    const bench::BucketRow r = bench::measureBuckets({o.layers, o.k, o.repeats, width, height}, m);
    const double xWall = r.bruteQuery.wallMs / r.bucketQuery.wallMs, xCpu = r.bruteQuery.cpuMs / r.bucketQuery.cpuMs;
    if (o.json) {
      rows.push_back({{"objects", m}, {"layers", o.layers}, {"k", o.k}, {"fragments", r.fragments},
                      {"z_insert_ms", r.zInsertMs}, {"buckets_ms", r.bucketsMs}, {"data_ms", r.dataMs},
                      {"neighbors_buckets_ms", r.bucketQuery.wallMs}, {"neighbors_brute_force_ms", r.bruteQuery.wallMs},
                      {"neighbors_buckets_cpu_ms", r.bucketQuery.cpuMs}, {"neighbors_brute_force_cpu_ms", r.bruteQuery.cpuMs},
                      {"speedup_wall", xWall}, {"speedup_cpu", xCpu}, {"curvature_ms", r.curvatureMs},
                      {"plain_kbuffer_frame_ms", r.plainFrame.wallMs}, {"plain_kbuffer_frame_cpu_ms", r.plainFrame.cpuMs},
                      {"bytes_per_fragment_buckets", bucketBytes}, {"bytes_per_fragment_brute_force", bruteBytes}});
    } else {
      std::printf("%7d %9llu %8.1f %7.1f %7.1f %9.1f %9.1f %9.1f %9.1f %7.2f %7.2f %9.1f %10.1f\n", m,
                  static_cast<unsigned long long>(r.fragments), r.zInsertMs, r.bucketsMs, r.dataMs, r.bucketQuery.wallMs,
                  r.bruteQuery.wallMs, r.bucketQuery.cpuMs, r.bruteQuery.cpuMs, xWall, xCpu, r.curvatureMs,
                  r.plainFrame.wallMs);
      std::fflush(stdout);
    }
  }
  if (o.json) std::cout << rows.dump(2) << "\n";
}

}  // namespace

void addBucketBench(CLI::App& bench) {
  auto o = std::make_shared<BucketBenchOptions>();
  auto* cmd = bench.add_subcommand(
      "buckets", "Neighbour query of the bucketed k-buffer vs. brute force on 32 stacked quads (Murray et al. Fig. 10)");
  cmd->add_option("--size", o->size, "image size WxH")->capture_default_str();
  cmd->add_option("--layers", o->layers, "quads in the stack")->capture_default_str()->check(CLI::Range(1, 4096));
  cmd->add_option("--k", o->k, "fragments kept per pixel")->capture_default_str()->check(CLI::Range(1, 32));
  cmd->add_option("--objects", o->objects, "object counts to measure")->capture_default_str();
  cmd->add_option("--repeats", o->repeats, "timed frames per configuration (median)")->capture_default_str()->check(CLI::Range(1, 100));
  cmd->add_flag("--json", o->json, "print JSON");
  cmd->callback([o] { runBucketBench(*o); });
}

}  // namespace tlab::app
