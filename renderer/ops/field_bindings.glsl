// Binding points of the per-fragment transparency fields (Carnecky Sec. 5.1) and neighbour links
// (Sec. 4.4). Each field is its own array so a style pays only for the fields it uses.
#define BIND_LINKS 10
#define BIND_ALPHA_IN 11
#define BIND_ALPHA_OUT 12
#define BIND_BETA_IN 13
#define BIND_BETA_OUT 14
#define BIND_GAMMA_IN 15
#define BIND_GAMMA_OUT 16
#define BIND_FLAGS 17
#define BIND_ALPHA_OLD 18
#define BIND_CHANGED 19  // one word: bit 1 β changed, bit 2 γ changed (fused spreading)
#define BIND_CONNECT_WORK 22  // the connect pass's work list: a count, then pairs of pixels (ops/connect.comp)
#define BIND_CONNECT_PAIRS 25  // the connect pass's links of each pixel's pairs as bits (ops/connect.comp, TLAB_LINK_MASKS)
// Sparse Eq. 9 spreading (ops/spread_frontier.comp): fragment lists, each a dispatch header
// (groups, 1, 1, count) then fragment indices; the connect pass lists β's and γ's seeds.
#define BIND_FRONTIER_IN 23
#define BIND_FRONTIER_OUT 24
#define BIND_SEEDS_BETA 23
#define BIND_SEEDS_GAMMA 24
#define FRONTIER_GROUP 64u       // invocations per group of a frontier dispatch
#define FRONTIER_MAX_GROUPS 65535u

#define NO_NEIGHBOR 0xFFFFFFFFu
// Flag bits: set = free (b = 1 in the paper), clear = fixed by a boundary condition (b = 0).
#define FREE_ALPHA 1u
#define FREE_BETA 2u
#define FREE_GAMMA 4u

// A frontier list as a storage block (instance name `list`), and reserving N entries of it from
// index AT with one atomic (nothing for N = 0: on a CPU rasterizer an atomic runs lane by lane for
// every lane that reaches it, and two threads adding to one word pass it between their caches —
// the connect pass's phase 2 took 6.7 ms on the torus with an atomic for every list, 3.7 without):
// the header's group count stays ⌈count / FRONTIER_GROUP⌉ (up to the dispatch limit; frontier
// passes loop over the rest), so the list is the next pass's indirect dispatch.
#define FRONTIER_LIST(ACCESS, BINDING, NAME, list) \
  layout(std430, binding = BINDING) ACCESS buffer NAME { uint groups; uint one_y; uint one_z; uint count; uint items[]; } list
#define FRONTIER_RESERVE(list, N, AT)                                                             \
  if ((N) > 0u) {                                                                                 \
    AT = atomicAdd(list.count, (N));                                                              \
    uint groups_ = min((AT + (N) + FRONTIER_GROUP - 1u) / FRONTIER_GROUP, FRONTIER_MAX_GROUPS) -  \
                   min((AT + FRONTIER_GROUP - 1u) / FRONTIER_GROUP, FRONTIER_MAX_GROUPS);         \
    if (groups_ > 0u) atomicAdd(list.groups, groups_);                                            \
  }
// Appends fragment FIRST + i for each bit i of MASK.
#define FRONTIER_APPEND_LAYERS(list, MASK, FIRST)                                                 \
  {                                                                                               \
    uint at_ = 0u;                                                                                \
    FRONTIER_RESERVE(list, uint(bitCount(MASK)), at_);                                            \
    for (uint m_ = (MASK); m_ != 0u; m_ &= m_ - 1u) list.items[at_++] = (FIRST) + uint(findLSB(m_)); \
  }
