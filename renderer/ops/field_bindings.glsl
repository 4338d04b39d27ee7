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
#define BIND_CONNECT_WORK 22  // the connect pass's work list: a count, then pixels (ops/connect.comp)

#define NO_NEIGHBOR 0xFFFFFFFFu
// Flag bits: set = free (b = 1 in the paper), clear = fixed by a boundary condition (b = 0).
#define FREE_ALPHA 1u
#define FREE_BETA 2u
#define FREE_GAMMA 4u
