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

// What the traffic of a frame depends on.
struct FrameShape {
  std::uint64_t pixels = 0;
  std::uint64_t fragments = 0;
  std::uint32_t recordWords = 2;   // words per fragment record (render::FragmentLayout::stride)
  std::uint32_t composeWords = 2;  // words of each record the style's compositor reads
  int fieldsPerFragment = 1;       // smart: α plus β (silhouettes) plus γ (halos)
  int solveDispatches = 0;         // smart: compute dispatches of the solve pass
};

// The shape of the frame `stats` describes, rendered with `style` and its resolved parameters.
FrameShape frameShape(const render::RenderStats& stats, const std::string& style, const render::StyleParams& params);

// The floor of each modelled pass of `passes` (the names the Renderer timed); passes the model
// does not know are left out.
std::vector<PassTraffic> passTraffic(const FrameShape& shape, const std::vector<std::string>& passes);

// Bytes per second of a streaming copy (read + write counted) of `bytes` with `threads` threads,
// the best of `repeats`.
double streamingBandwidth(std::size_t bytes, int threads, int repeats);

}  // namespace tlab::bench
