// tlab bench buckets: the synthetic benchmark of seed 002 (Murray et al., Sec. 6, Fig. 10):
// `quad-stack` with 32 full-screen quads at random depths, 512x512 (about 8.4 M fragments),
// the quads spread over 1, 2, 4, 8, 16, 32 objects (shapes). Per object count: the time of the
// neighbour query with buckets and by brute force (every fragment of the adjacent pixel,
// filtered by shape, as in the illustration buffer), the k-buffer passes, and a plain k-buffer
// frame with constant opacity as the floor. Target: buckets >= 5x faster at >= 16 objects.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/scene_options.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/scene_source.hpp"

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

// Median per-pass milliseconds over `repeats` frames after one warm-up frame.
std::map<std::string, double> medianPasses(render::Renderer& renderer, const render::RenderRequest& request, int repeats,
                                           render::RenderStats& stats) {
  renderer.render(request, &stats);
  std::map<std::string, std::vector<double>> samples;
  for (int i = 0; i < repeats; ++i) {
    renderer.render(request, &stats);
    double total = 0;
    for (const auto& [name, ms] : stats.passMilliseconds) {
      samples[name].push_back(ms);
      total += ms;
    }
    samples["total"].push_back(total);
  }
  std::map<std::string, double> median;
  for (auto& [name, v] : samples) {
    std::sort(v.begin(), v.end());
    median[name] = v[v.size() / 2];
  }
  return median;
}

void runBucketBench(const BucketBenchOptions& o) {
  const auto context = gpu::createHeadlessContext();
  render::RenderRequest base;
  std::tie(base.width, base.height) = parseSize(o.size);
  base.style = "curvature";
  base.timePasses = true;
  const auto with = [&](const std::string& mode, const std::string& query) {
    render::RenderRequest r = base;
    r.settings = {{"k", std::to_string(o.k)}, {"mode", mode}, {"query", query}};
    return r;
  };
  // Bytes per fragment slot: Z + B + D (+ links + κ) with buckets; Z + D (+ links + κ) without B.
  const std::size_t bucketBytes = 4 + 4 + 8 + render::BucketedKBuffer::kLinkBytesPerSlot;
  const std::size_t bruteBytes = 4 + 8 + render::BucketedKBuffer::kLinkBytesPerSlot;
  nlohmann::json rows = nlohmann::json::array();
  if (!o.json) {
    std::printf("tlab bench buckets: quad-stack n=%d, %dx%d, k=%d, median of %d frames (ms); target buckets >= 5x "
                "faster than brute force at >= 16 objects\n",
                o.layers, base.width, base.height, o.k, o.repeats);
    std::printf("memory per fragment: buckets %zu B (Z 4 + B 4 + D 8 + links 4 + kappa 4), brute force %zu B (no B); "
                "plain k-buffer 12 B (Z 4 + D 8)\n",
                bucketBytes, bruteBytes);
    std::printf("%7s %10s %8s %8s %8s %10s %10s %8s %9s %10s %10s\n", "objects", "fragments", "z-insert", "buckets",
                "data", "nbr_bucket", "nbr_brute", "speedup", "curvature", "frame_bkt", "plain_kbuf");
  }
  for (int m : o.objects) {
    const render::Scene scene = render::loadScene("builtin:quad-stack?n=" + std::to_string(o.layers) + "&m=" + std::to_string(m));
    render::Renderer renderer(scene);
    render::RenderStats stats;
    const auto bucket = medianPasses(renderer, with("shading", "buckets"), o.repeats, stats);
    const std::uint64_t fragments = stats.fragments;
    const auto brute = medianPasses(renderer, with("shading", "brute-force"), o.repeats, stats);
    const auto plain = medianPasses(renderer, with("plain", "buckets"), o.repeats, stats);
    const double speedup = brute.at("neighbors") / bucket.at("neighbors");
    if (o.json) {
      rows.push_back({{"objects", m}, {"layers", o.layers}, {"k", o.k}, {"fragments", fragments},
                      {"z_insert_ms", bucket.at("z-insert")}, {"buckets_ms", bucket.at("buckets")},
                      {"data_ms", bucket.at("data")}, {"neighbors_buckets_ms", bucket.at("neighbors")},
                      {"neighbors_brute_force_ms", brute.at("neighbors")}, {"speedup", speedup},
                      {"curvature_ms", bucket.at("curvature")}, {"frame_buckets_ms", bucket.at("total")},
                      {"frame_brute_force_ms", brute.at("total")}, {"plain_kbuffer_ms", plain.at("total")},
                      {"bytes_per_fragment_buckets", bucketBytes}, {"bytes_per_fragment_brute_force", bruteBytes}});
    } else {
      std::printf("%7d %10llu %8.1f %8.1f %8.1f %10.1f %10.1f %8.2f %9.1f %10.1f %10.1f\n", m,
                  static_cast<unsigned long long>(fragments), bucket.at("z-insert"), bucket.at("buckets"),
                  bucket.at("data"), bucket.at("neighbors"), brute.at("neighbors"), speedup, bucket.at("curvature"),
                  bucket.at("total"), plain.at("total"));
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
