#include "bench/measure/traffic_floor.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <thread>

#include "renderer/buffer/fragment_layout.hpp"
#include "renderer/gpu/gl_objects.hpp"
#include "renderer/ops/smart_settings.hpp"
#include "renderer/ops/transparency_fields.hpp"
#include "renderer/styles/style.hpp"

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

constexpr std::uint32_t kFreeBeta = 2, kFreeGamma = 4;  // FREE_BETA, FREE_GAMMA of ops/field_bindings.glsl

SolveShape solveShape(const render::SmartSettings& smart, const render::TransparencyFields* fields) {
  SolveShape s;
  s.alphaSweeps = smart.iterations * smart.alphaDispatchesPerStep();
  s.alphaImplicit = smart.scheme == render::DiffusionScheme::Implicit;
  if (!smart.spreadByMax) {
    const auto sweeps = [&](bool on, double lambda) {
      return on ? smart.iterations * render::substepsFor(lambda, render::kExplicitStableLambdaSum) : 0;
    };
    s.betaSweeps = sweeps(smart.silhouettes, smart.lambdaBeta);
    s.gammaSweeps = sweeps(smart.halos, smart.lambdaGamma);
    return s;
  }
  if (!fields || fields->fragments() == 0) return s;
  const std::vector<std::uint32_t> flags = fields->readFlags();
  if (fields->hasBeta()) {
    const SpreadCount c = countSpread(fields->read(render::Field::Beta), flags, kFreeBeta);
    s.betaSeeds = c.seeds, s.betaReached = c.reached;
  }
  if (fields->hasGamma()) {
    const SpreadCount c = countSpread(fields->read(render::Field::Gamma), flags, kFreeGamma);
    s.gammaSeeds = c.seeds, s.gammaReached = c.reached;
  }
  return s;
}

}  // namespace

SpreadCount countSpread(const std::vector<float>& values, const std::vector<std::uint32_t>& flags, std::uint32_t freeBit) {
  SpreadCount c;
  for (std::size_t i = 0; i < values.size() && i < flags.size(); ++i) {
    if (!(values[i] > 0.0f)) continue;
    if (flags[i] & freeBit) ++c.reached;
    else ++c.seeds;
  }
  return c;
}

FrameShape frameShape(const render::RenderStats& stats, const std::string& style, const render::StyleParams& params,
                      const render::TransparencyFields* fields) {
  FrameShape s;
  s.pixels = std::uint64_t(stats.width) * std::uint64_t(stats.height);
  s.fragments = stats.fragments;
  const render::FragmentLayout layout(propertiesNamed(stats.fragmentProperties));
  s.recordWords = layout.stride;
  s.dataWords = layout.words;
  s.listSteps = layout.properties.has(render::FragmentProperty::DepthGradient);
  const render::FillSpec fill = render::findStyle(style).fill(params);
  s.colorPlane = fill.colorPlane && layout.properties.has(render::FragmentProperty::Color);
  s.sortsInCompose = fill.sortsInCompose;
  s.hostBlend = gpu::hostPassesWanted() && (style == "constant" || style == "smart");
  // The fill stores and the sort copies whole records, their padding too (uvec4 at a time); the
  // passes that read records read only the words they use. A compositor reads every property of the
  // record (constant's, which sorts each list as it blends (issue #29), its depth and triangle for
  // the sort and its colour); smart's reads the colour and the solved fields.
  s.composeWords = layout.words;
  if (style == "smart") {
    const auto smart = render::SmartSettings::from(params);
    s.solve = solveShape(smart, fields);
    s.composeWords = 1;
    // α only where it varies (Eq. 5; Eq. 4's s is a uniform), β and γ only where the connect pass
    // listed a seed (a field of zeros is left out: render/compose/smart_compositor.cpp).
    const auto varies = [&](bool has, render::Field f) { return has && !(fields && fields->allZero(f)) ? 1 : 0; };
    s.composeFields = (smart.adaptiveAlpha ? 1 : 0) + varies(smart.silhouettes, render::Field::Beta) +
                      varies(smart.halos, render::Field::Gamma);
    // The connect pass stores the same fields for each fragment (a listed field with seeds is
    // cleared, then set at its seeds: counted as one store each), the others are one number.
    s.fieldsPerFragment = s.composeFields;
    const auto has = [&](render::FragmentProperty p) { return layout.properties.has(p) ? 1u : 0u; };
    s.linkPairBits = fields && fields->linksFromPairBits();
    s.connectPhase2 = !fields || fields->linksStored();
    s.connectWords = 1 + has(render::FragmentProperty::Normal) + 2 * has(render::FragmentProperty::DepthGradient) +
                     has(render::FragmentProperty::Ids);
  }
  return s;
}

std::vector<PassTraffic> passTraffic(const FrameShape& s, const std::vector<std::string>& passes) {
  const double px = double(s.pixels), fr = double(s.fragments);
  const double record = 4.0 * s.recordWords;
  const std::string recordText = std::to_string(s.recordWords) + " words" +
                                 (s.recordWords > s.dataWords ? " with " + std::to_string(s.recordWords - s.dataWords) + " of padding" : "");
  std::vector<PassTraffic> out;
  // A compositor that sorts, after a sort that wrote the colour plane alone (FrameShape::sortsInCompose).
  const bool planeOnly = s.sortsInCompose && std::find(passes.begin(), passes.end(), "sort") != passes.end();
  for (const auto& name : passes) {
    PassTraffic t;
    t.pass = name;
    if (name == "fill") {
      t.bytesWritten = fr * record + px * 8;
      t.model = "writes each record once (" + recordText + "), a count and a head per pixel";
    } else if (name == "sort" && planeOnly) {
      t.bytesRead = fr * 4.0 * 3 + px * 8;
      t.bytesWritten = fr * 4;
      t.model = "reads count, head and each record's depth, triangle and colour once, writes each colour word once "
                "in sorted order (the colour plane, for a compositor that sorts)";
    } else if (name == "sort") {
      t.bytesRead = fr * record + px * 8;
      t.bytesWritten = fr * record + (s.listSteps ? px * 8 : 0) + (s.colorPlane ? fr * 4 : 0);
      t.model = "reads count, head and each record once, writes each record once (" + recordText + ")" +
                (s.listSteps ? " and each list's maxStep (two floats a pixel)" : "") +
                (s.colorPlane ? " and each colour word again (the colour plane)" : "");
    } else if (name == "compose") {
      // After a sort of the colours (planeOnly) the compositor reads the colour plane alone; blended
      // as host code, the image is written once, with no output buffer to read back.
      const std::uint32_t words = planeOnly ? 1 : s.composeWords;
      const bool host = s.hostBlend && (planeOnly || !s.sortsInCompose);
      t.bytesRead = px * (host ? 8 : 8 + 16) + fr * 4.0 * (words + s.composeFields);
      t.bytesWritten = px * (host ? 16 : 16 + 16);
      t.model = "reads count, head and " + std::to_string(words) +
                (s.colorPlane || planeOnly ? " word(s) of the colour plane" : " word(s) of each record") +
                (s.composeFields ? " and " + std::to_string(s.composeFields) + " field(s)" : std::string()) +
                (host ? " per fragment; writes the image (RGBA32F per pixel: host code, no read-back)"
                      : " per fragment; writes RGBA32F per pixel, read back into the image");
    } else if (name == "connect") {
      // Phase 1 reads count, head and maxStep (written by the sort) of each pixel and the words ε
      // needs of each record once (depth, ∇z, normal, ids), and writes each link once (each pair
      // of adjacent pixels settled once); phase 2 reads count and head again and each fragment's
      // own links, and writes the fields and the flags. Phase 3's full search of the few listed
      // pairs depends on the scene and is not counted. With the links kept as pair bits, phase 1
      // writes 16 bytes a pixel instead, which phase 2 reads before it writes each fragment's links.
      // Where every fragment's links join the same layer all round, phase 2 is left out
      // (ConnectOutput::WhatTheFrameReads): the pair words are written, and nothing is read back.
      const std::string phase1 =
          "maxStep (from the sort) read per pixel; " + std::to_string(s.connectWords) + " word(s) of each record read once; ";
      if (!s.connectPhase2) {
        t.bytesRead = px * 16 + fr * 4.0 * s.connectWords;
        t.bytesWritten = px * 16;
        t.model = phase1 + "links as bits of each pixel's pairs (16 bytes a pixel written), every fragment linked all round: "
                           "phase 2 left out";
      } else {
        t.bytesRead = px * (16 + 8) + fr * 4.0 * s.connectWords + (s.linkPairBits ? px * 16 : fr * 16);
        t.bytesWritten = fr * (16 + 4.0 * s.fieldsPerFragment + 4) + (s.linkPairBits ? px * 16 : 0);
        t.model = phase1 +
                  (s.linkPairBits ? "links as bits of each pixel's pairs (16 bytes a pixel, written and read once), then written once"
                                  : "links written once and read once") +
                  "; " + std::to_string(s.fieldsPerFragment) + " field(s) stored for each fragment and the flags written";
      }
    } else if (name == "solve") {
      // Per full sweep (α by Eq. 8, or β, γ by Eq. 8 spreading) each fragment's links, flags and
      // value are read and its value written (its neighbours' values are other fragments' own,
      // counted once with perfect caches). Eq. 9 on the frontier: the links and value of every
      // seed and every fragment reached, the flags of those reached, and their values written.
      const SolveShape& v = s.solve;
      const double sweepRead = fr * (16 + 4 + 4), sweepWrite = fr * 4;
      const int sweeps = v.alphaSweeps + v.betaSweeps + v.gammaSweeps;
      const double seeds = double(v.betaSeeds + v.gammaSeeds), reached = double(v.betaReached + v.gammaReached);
      t.bytesRead = sweeps * sweepRead + (v.alphaImplicit ? v.alphaSweeps * fr * 4 : 0) + (seeds + reached) * (16 + 4) +
                    reached * 4;
      t.bytesWritten = sweeps * sweepWrite + reached * 4;
      t.model = std::to_string(sweeps) + " full sweep(s) of links, flags and value" +
                (v.alphaImplicit ? " (Jacobi: and alpha before the step)" : "") + "; Eq. 9 on the frontier: " +
                std::to_string(v.betaSeeds + v.gammaSeeds) + " seeds and " + std::to_string(v.betaReached + v.gammaReached) +
                " fragments reached (beta and gamma): the links and value of each read, the flags of those reached read and "
                  "their values written";
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
