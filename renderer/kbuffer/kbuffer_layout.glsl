// The bucketed k-buffer's buffers (seed 002, Sec. 4) and their packing; the CPU model is
// kbuffer/bucket_table.hpp. TLAB_K slots per pixel, pixel p owns slots [p·K, p·K + K).
#define BIND_KB_Z 0
#define BIND_KB_TABLE 1
#define BIND_KB_DATA 2
#define BIND_KB_LINKS 3
#define BIND_KB_CURVATURE 4
#define BIND_KB_OUTPUT 9
#define BIND_KB_TRANSFER 10

#ifndef TLAB_K
#define TLAB_K 16u
#endif
#define KB_EMPTY 0xFFFFFFFFu
#define KB_NO_NEIGHBOR 0xFFFFFFFFu
// Links: one word per slot, byte d = the neighbour's layer in the adjacent pixel in direction d
// (left, right, down, up), KB_NO_LINK when there is none.
#define KB_NO_LINK 0xFFu
const ivec2 kDirections[4] = ivec2[4](ivec2(-1, 0), ivec2(1, 0), ivec2(0, -1), ivec2(0, 1));
uint linkLayer(uint links, int d) { return (links >> (8 * d)) & 0xFFu; }

uint slotOf(uint pixel, uint layer) { return pixel * uint(TLAB_K) + layer; }

// Sec. 4.2: depth (16 bits) as MSB for the Z pass; swapped to shape id as MSB for the reorder.
uint packDepthFirst(uint depth16, uint shape) { return (depth16 << 16) | (shape & 0xFFFFu); }
uint swapHalves(uint key) { return (key << 16) | (key >> 16); }
uint shapeOfShapeFirst(uint key) { return key >> 16; }
float depthOfShapeFirst(uint key) { return float(key & 0xFFFFu) / 65535.0; }
float depthOfDepthFirst(uint key) { return float(key >> 16) / 65535.0; }

// B: shape id (16 bits) | first (8 bits) | last (8 bits).
uint bucketShape(uint word) { return word >> 16; }
uint bucketFirst(uint word) { return (word >> 8) & 0xFFu; }
uint bucketLast(uint word) { return word & 0xFFu; }
