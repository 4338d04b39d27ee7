#pragma once
// The memory-traffic floor of a frame (`tlab bench floor`, issue #29): for each pass, the bytes it
// must read and write at the least — every buffer element its job touches, counted once, as if
// caches were perfect — and this machine's streaming bandwidth, measured with a plain copy. A
// pass's floor time is its bytes over that bandwidth; its measured time over the floor says how
// far it is from the memory limit (1 = streaming speed). llvmpipe runs every pass on the CPU, so
// the CPU's bandwidth is the one that bounds it.
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/params/style_params.hpp"
#include "renderer/pipeline/renderer.hpp"

namespace tlab::bench {

struct PassTraffic {
  std::string pass;
  double bytesRead = 0, bytesWritten = 0;  // per frame
  std::string model;                       // what was counted, per pixel and per fragment
};

// What smart's solve pass works on.
struct SolveShape {
  int alphaSweeps = 0;  // Eq. 8 sweeps of α over every fragment (steps × dispatches per step)
  bool alphaImplicit = false;  // Jacobi sweeps, which also read α before the step
  int betaSweeps = 0, gammaSweeps = 0;  // Eq. 8 spreading sweeps over every fragment (spread=diffusion)
  // Eq. 9 spreading on the frontier (spread=max): per field, the fragments it spreads from and those it reached.
  std::uint64_t betaSeeds = 0, betaReached = 0, gammaSeeds = 0, gammaReached = 0;
};

// Eq. 9's seeds of a field (fixed by the boundary conditions, above 0) and the fragments its
// spreading reached (free, above 0), from the field's values and the flags (`freeBit` of the field).
struct SpreadCount {
  std::uint64_t seeds = 0, reached = 0;
};
SpreadCount countSpread(const std::vector<float>& values, const std::vector<std::uint32_t>& flags, std::uint32_t freeBit);

// What the traffic of a frame depends on.
struct FrameShape {
  std::uint64_t pixels = 0;
  std::uint64_t fragments = 0;
  std::uint32_t recordWords = 2;   // words per fragment record, padding included (render::FragmentLayout::stride)
  std::uint32_t dataWords = 2;     // of those, the words the properties take (render::FragmentLayout::words)
  std::uint32_t composeWords = 2;  // words of each record the style's compositor reads
  int composeFields = 0;           // smart: the fields (α, β, γ) its compositor reads per fragment (those that vary)
  std::uint32_t connectWords = 0;  // smart: the words of each record the connect pass reads (depth, ∇z, normal, ids)
  bool listSteps = false;          // records with a depth gradient: the sort also writes each list's maxStep
  bool colorPlane = false;         // the sort also writes each colour word into a plane (render::FillSpec::colorPlane)
  // The compositor sorts (render::FillSpec::sortsInCompose): a "sort" pass, where one ran, wrote
  // the colour plane alone (the sort as host code, where the GL runs on the CPU), which the
  // compositor then reads in place of the records.
  bool sortsInCompose = false;
  // The compositor blends as host code straight into the image (`constant` and smart where the
  // host passes run: render/compose/host_blend.hpp): no RGBA32F output to write and read back.
  bool hostBlend = false;
  int fieldsPerFragment = 1;       // smart: the fields the connect pass stores (those that vary)
  bool connectPhase2 = true;        // smart: whether the connect pass ran its phase 2 (else the links were not stored)
  bool linkPairBits = false;       // smart: the connect pass kept its settled links as bits of each pixel's pairs
  SolveShape solve;                // smart
};

// The shape of the frame `stats` describes, rendered with `style` and its resolved parameters;
// for smart, `fields` are the renderer's fields after that frame (the solve's spreading is counted there).
FrameShape frameShape(const render::RenderStats& stats, const std::string& style, const render::StyleParams& params,
                      const render::TransparencyFields* fields = nullptr);

// The floor of each modelled pass of `passes` (the names the Renderer timed); passes the model
// does not know are left out.
std::vector<PassTraffic> passTraffic(const FrameShape& shape, const std::vector<std::string>& passes);

// Bytes per second of a streaming copy (read + write counted) of `bytes` with `threads` threads,
// the best of `repeats`.
double streamingBandwidth(std::size_t bytes, int threads, int repeats);

}  // namespace tlab::bench
