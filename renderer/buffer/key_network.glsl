// Sorting a pixel's keys in registers (issue #29): Batcher's odd-even merge network (Knuth, TAOCP
// 3, Sec. 5.3.4) of NET_SIZE inputs, 8 (19 compare-exchanges) or 16 (63), which the includer
// defines first. A key is (depth bits, tie-break) with each word's top bit flipped (NET_FLIP), so
// that keys compare as signed integers (one CPU instruction) in the order of the unsigned words.
// Every index into netKeys is a constant, so the keys stay in registers: llvmpipe runs the network
// once for a group of lanes, where an insertion sort in memory loops per lane. Used by the sort pass
// (buffer/sort.comp) and by the compose pass that sorts as it blends (compose/blend.comp).
//   netClear(); for each key: NET_PUSH(key); NET_SORT; then front to back: read netKeys[0], NET_NEXT.
ivec2 netKeys[NET_SIZE];
const uint NET_FLIP = 0x80000000u;
bool netBefore(ivec2 a, ivec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
// The key of a list's i-th fragment (i < 16): (depth bits, triangle * 16 + i), flipped; the
// order (depth, triangle, position). netPosition reads i back, netWords the unflipped words.
ivec2 netKey(uint depthBits, uint triangle, uint i) { return ivec2(uvec2(depthBits, (triangle << 4u) | i) ^ NET_FLIP); }
uvec2 netWords(ivec2 key) { return uvec2(key) ^ NET_FLIP; }
uint netPosition(ivec2 key) { return netWords(key).y & 15u; }
// No key: 0xFFFFFFFF unflipped, after every real key (a depth is never NaN).
void netClear() {
  for (uint k = 0u; k < uint(NET_SIZE); ++k) netKeys[k] = ivec2(0x7FFFFFFF);
}
// Compare-exchange: the smaller key to netKeys[a], the larger to netKeys[b] (a < b).
#define NET_CE(a, b) { ivec2 lo = netKeys[a], hi = netKeys[b]; bool swap = netBefore(hi, lo); \
  netKeys[a] = swap ? hi : lo; netKeys[b] = swap ? lo : hi; }
#define NET_SORT4(o) NET_CE(o, o + 1u) NET_CE(o + 2u, o + 3u) NET_CE(o, o + 2u) NET_CE(o + 1u, o + 3u) NET_CE(o + 1u, o + 2u)
// Merges the sorted netKeys[o..o+3] and netKeys[o+4..o+7].
#define NET_MERGE8(o) NET_CE(o, o + 4u) NET_CE(o + 2u, o + 6u) NET_CE(o + 2u, o + 4u) NET_CE(o + 1u, o + 5u) \
  NET_CE(o + 3u, o + 7u) NET_CE(o + 3u, o + 5u) NET_CE(o + 1u, o + 2u) NET_CE(o + 3u, o + 4u) NET_CE(o + 5u, o + 6u)
#define NET_SORT8(o) NET_SORT4(o) NET_SORT4(o + 4u) NET_MERGE8(o)
#define NET_UP(k) netKeys[k] = netKeys[k - 1u];
#define NET_POP(k) netKeys[k] = netKeys[k + 1u];
#if NET_SIZE == 16
// Merges the sorted netKeys[0..7] and netKeys[8..15].
#define NET_MERGE16 NET_CE(0u, 8u) NET_CE(4u, 12u) NET_CE(4u, 8u) NET_CE(2u, 10u) NET_CE(6u, 14u) NET_CE(6u, 10u) \
  NET_CE(2u, 4u) NET_CE(6u, 8u) NET_CE(10u, 12u) NET_CE(1u, 9u) NET_CE(5u, 13u) NET_CE(5u, 9u) NET_CE(3u, 11u)     \
  NET_CE(7u, 15u) NET_CE(7u, 11u) NET_CE(3u, 5u) NET_CE(7u, 9u) NET_CE(11u, 13u) NET_CE(1u, 2u) NET_CE(3u, 4u)      \
  NET_CE(5u, 6u) NET_CE(7u, 8u) NET_CE(9u, 10u) NET_CE(11u, 12u) NET_CE(13u, 14u)
// The key into netKeys[0], the earlier ones one register up.
#define NET_PUSH(key) NET_UP(15u) NET_UP(14u) NET_UP(13u) NET_UP(12u) NET_UP(11u) NET_UP(10u) NET_UP(9u) NET_UP(8u) \
  NET_UP(7u) NET_UP(6u) NET_UP(5u) NET_UP(4u) NET_UP(3u) NET_UP(2u) NET_UP(1u) netKeys[0] = key;
#define NET_SORT NET_SORT8(0u) NET_SORT8(8u) NET_MERGE16
// Drops netKeys[0]: the next key moves into it.
#define NET_NEXT NET_POP(0u) NET_POP(1u) NET_POP(2u) NET_POP(3u) NET_POP(4u) NET_POP(5u) NET_POP(6u) \
  NET_POP(7u) NET_POP(8u) NET_POP(9u) NET_POP(10u) NET_POP(11u) NET_POP(12u) NET_POP(13u) NET_POP(14u)
#else
#define NET_PUSH(key) NET_UP(7u) NET_UP(6u) NET_UP(5u) NET_UP(4u) NET_UP(3u) NET_UP(2u) NET_UP(1u) netKeys[0] = key;
#define NET_SORT NET_SORT8(0u)
#define NET_NEXT NET_POP(0u) NET_POP(1u) NET_POP(2u) NET_POP(3u) NET_POP(4u) NET_POP(5u) NET_POP(6u)
#endif
