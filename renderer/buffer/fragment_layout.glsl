// The layout of one fragment record in the illustration buffer (Carnecky Sec. 4.1, fragData):
// TLAB_STRIDE 32-bit words per fragment; words 0-1 are always depth and the sort key; the rest
// exist only when the style asked for them (TLAB_HAS_* / TLAB_OFF_* come from FragmentLayout).
// Binding points shared by every illustration-buffer pass.
#define BIND_PIXEL_COUNT 0
#define BIND_PIXEL_HEAD 1
#define BIND_PIXEL_CURSOR 2
#define BIND_LIST_NEXT 3
#define BIND_COUNTERS 4
#define BIND_FRAGS_UNSORTED 5
#define BIND_FRAGS_SORTED 6
#define BIND_ORDER 7
#define BIND_OBJECTS 8
#define BIND_OUTPUT 9

#ifndef TLAB_STRIDE
#define TLAB_STRIDE 2u  // passes that read no fragment records
#endif

#define OFF_DEPTH 0u
#define OFF_PRIM 1u

uint fragWord(uint frag, uint offset) { return frag * uint(TLAB_STRIDE) + offset; }
