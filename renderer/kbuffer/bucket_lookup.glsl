// Finding a bucket and a fragment in it (seed 002, Fig. 4). Needs `table` (B) and `z` (Z).
// Returns the bucket word of `shape` in the pixel whose slots start at `base`, or KB_EMPTY:
// linear probing from H(b) = b mod k until the shape or a free slot is met.
uint findBucket(uint base, uint shape) {
  uint slot = shape % uint(TLAB_K);
  for (uint probe = 0u; probe < uint(TLAB_K); ++probe) {
    uint word = table[base + slot];
    if (word == KB_EMPTY || bucketShape(word) == shape) return word;
    slot = (slot + 1u) % uint(TLAB_K);
  }
  return KB_EMPTY;
}
