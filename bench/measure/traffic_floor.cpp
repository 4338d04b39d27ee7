#include "bench/measure/traffic_floor.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <thread>

#include "renderer/buffer/fragment_layout.hpp"
#include "renderer/ops/smart_settings.hpp"

namespace tlab::bench {

namespace {

render::FragmentProperties propertiesNamed(const std::vector<std::string>& names) {
  static const std::map<std::string, render::FragmentProperty> byName = {
      {"color", render::FragmentProperty::Color},
      {"normal", render::FragmentProperty::Normal},
      {"depth_gradient", render::FragmentProperty::DepthGradient},
      {"ids", render::FragmentProperty::Ids},
      {"st", render::FragmentProperty::SurfaceParams},
      {"nz_gradient", render::FragmentProperty::NormalZGradient},
      {"st_gradient", render::FragmentProperty::StGradient},
  };
  render::FragmentProperties p;
  for (const auto& n : names)
    if (const auto it = byName.find(n); it != byName.end()) p |= it->second;
  return p;
}

}  // namespace

FrameShape frameShape(const render::RenderStats& stats, const std::string& style, const render::StyleParams& params) {
  FrameShape s;
  s.pixels = std::uint64_t(stats.width) * std::uint64_t(stats.height);
  s.fragments = stats.fragments;
  s.recordWords = render::FragmentLayout(propertiesNamed(stats.fragmentProperties)).stride;
  // Every compositor reads whole records; constant's, which sorts each list as it blends (issue #29),
  // its depth and triangle for the sort and its colour.
  s.composeWords = s.recordWords;
  if (style == "smart") {
    const auto smart = render::SmartSettings::from(params);
    s.fieldsPerFragment = 1 + (smart.silhouettes ? 1 : 0) + (smart.halos ? 1 : 0);
  }
  return s;
}

std::vector<PassTraffic> passTraffic(const FrameShape& s, const std::vector<std::string>& passes) {
  const double px = double(s.pixels), fr = double(s.fragments);
  const double record = 4.0 * s.recordWords;
  std::vector<PassTraffic> out;
  for (const auto& name : passes) {
    PassTraffic t;
    t.pass = name;
    if (name == "fill") {
      t.bytesWritten = fr * record + px * 8;
      t.model = "writes each record once, a count and a head per pixel";
    } else if (name == "sort") {
      t.bytesRead = fr * record + px * 8;
      t.bytesWritten = fr * record;
      t.model = "reads count, head and each record once, writes each record once";
    } else if (name == "compose") {
      t.bytesRead = px * (8 + 16) + fr * 4.0 * s.composeWords;
      t.bytesWritten = px * (16 + 16);
      t.model = "reads count, head and " + std::to_string(s.composeWords) +
                " word(s) per fragment; writes RGBA32F per pixel, read back into the image";
    } else if (name == "connect") {
      t.bytesRead = px * 16 + fr * (record + 16);
      t.bytesWritten = fr * (16 + 16 + 4.0 * s.fieldsPerFragment + 4);
      t.model = "two phases: each record once, links written, read and rewritten, " +
                std::to_string(s.fieldsPerFragment) + " field(s) and the flags written";
    } else {
      continue;
    }
    out.push_back(t);
  }
  return out;
}

double streamingBandwidth(std::size_t bytes, int threads, int repeats) {
  std::vector<char> src(bytes, 1), dst(bytes, 0);  // touched once, so no page faults are timed
  const std::size_t part = bytes / std::size_t(threads);
  double best = 0;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t)
      workers.emplace_back([&, t] { std::memcpy(dst.data() + t * part, src.data() + t * part, part); });
    for (auto& w : workers) w.join();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, 2.0 * double(part * std::size_t(threads)) / s);
  }
  return best;
}

}  // namespace tlab::bench
