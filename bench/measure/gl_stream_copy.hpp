#pragma once
// The streaming rate a compute pass reaches on this GL (`tlab bench floor`, issue #29): compute
// shaders that only copy one buffer into another, with 1, 4 and 16 words per invocation. On
// llvmpipe every pass runs on the CPU, so the best of them is what a pass that did nothing but
// stream its bytes would reach; the CPU's memcpy (traffic_floor) is the hardware's limit, this
// the GL's.
#include <cstddef>
#include <vector>

namespace tlab::bench {

struct GlCopyRate {
  int wordsPerInvocation = 0;
  double bytesPerSecond = 0;  // read + write counted, the best of the repeats
};

// The copy of `bytes` with each of 1, 4 and 16 words per invocation; a GL context must be current.
std::vector<GlCopyRate> glStreamingRates(std::size_t bytes, int repeats);

// The fastest of them.
GlCopyRate fastest(const std::vector<GlCopyRate>& rates);

}  // namespace tlab::bench
