#pragma once
// The measurement of `tlab bench buckets` (seed 002, Murray et al., Sec. 6, Fig. 10): for one
// object count of the quad stack, the k-buffer passes, the neighbour query with buckets and by
// brute force on the same filled buffer, the curvature pass, and a whole plain k-buffer frame
// (the floor).
#include <cstdint>

#include "bench/measure/gl_timing.hpp"

namespace tlab::bench {

struct BucketBench {
  int layers = 32;   // quads in the stack
  int k = 32;        // fragments kept per pixel
  int repeats = 3;   // timed runs per figure (medians)
  int width = 512, height = 512;
};

struct BucketRow {
  int objects = 0;
  std::uint64_t fragments = 0;
  double zInsertMs = 0, bucketsMs = 0, dataMs = 0, curvatureMs = 0;
  GlTiming bucketQuery, bruteQuery, plainFrame;
};

// One object count: the k-buffer is filled once; the two neighbour queries then run
// alternately on the same buffer, `repeats` times each after a warm-up (medians).
BucketRow measureBuckets(const BucketBench& bench, int objects);

}  // namespace tlab::bench
