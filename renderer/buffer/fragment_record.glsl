// Writes the properties of the current fragment into record `frag` of `frags` (the style's
// FragmentLayout decides which exist). Included by the fill shaders.
in vec3 vViewPosition;
in vec3 vViewNormal;
in vec2 vST;
flat in uint vObject;
flat in uint vComponent;

uniform uint uPrimitiveBase;

// Screen-space derivatives must be taken in uniform control flow: call this first in main().
// The n_z and (s, t) derivatives are taken exactly as peel/peel_layer.frag takes them.
vec2 gDepthGradient;
vec2 gNzGradient;
vec4 gStGradient;
void captureDerivatives() {
  float depth = -vViewPosition.z;
  gDepthGradient = vec2(dFdx(depth), dFdy(depth));
  float nz = normalize(vViewNormal).z;
  gNzGradient = vec2(dFdx(nz), dFdy(nz));
  gStGradient = vec4(dFdx(vST.x), dFdy(vST.x), dFdx(vST.y), dFdy(vST.y));
}

// The record is put together in registers (every index a constant), then stored: as whole
// uvec4s where the layout pads it to quads of words (TLAB_RECORD_QUADS; the padding is 0), else
// word by word.
#ifdef TLAB_RECORD_QUADS
layout(std430, binding = BIND_FRAGS_UNSORTED) writeonly buffer Frags { uvec4 fragQuads[]; };
#else
layout(std430, binding = BIND_FRAGS_UNSORTED) writeonly buffer Frags { uint frags[]; };
#endif
void writeFragmentRecord(uint frag) {
  uint record[TLAB_STRIDE];
  for (uint w = 0u; w < uint(TLAB_STRIDE); ++w) record[w] = 0u;
  float depth = -vViewPosition.z;  // eye-space distance along the view axis
  record[OFF_DEPTH] = floatBitsToUint(depth);
  record[OFF_PRIM] = uPrimitiveBase + uint(gl_PrimitiveID);
#ifdef TLAB_HAS_COLOR
  record[TLAB_OFF_COLOR] = packUnorm4x8(vec4(shadeSurface(vObject, gl_FrontFacing, vViewNormal, vViewPosition), 1.0));
#endif
#ifdef TLAB_HAS_NORMAL
  record[TLAB_OFF_NORMAL] = encodeNormal(normalize(vViewNormal));
#endif
#ifdef TLAB_HAS_DEPTH_GRADIENT
  record[TLAB_OFF_DEPTH_GRADIENT + 0u] = floatBitsToUint(gDepthGradient.x);
  record[TLAB_OFF_DEPTH_GRADIENT + 1u] = floatBitsToUint(gDepthGradient.y);
#endif
#ifdef TLAB_HAS_IDS
  // object id (16 bits) | component id (15 bits) | front-facing flag (bit 31)
  record[TLAB_OFF_IDS] = (vObject & 0xFFFFu) | ((vComponent & 0x7FFFu) << 16) | (gl_FrontFacing ? 0x80000000u : 0u);
#endif
#ifdef TLAB_HAS_ST
  record[TLAB_OFF_ST + 0u] = floatBitsToUint(vST.x);
  record[TLAB_OFF_ST + 1u] = floatBitsToUint(vST.y);
#endif
#ifdef TLAB_HAS_NZ_GRADIENT
  record[TLAB_OFF_NZ_GRADIENT + 0u] = floatBitsToUint(gNzGradient.x);
  record[TLAB_OFF_NZ_GRADIENT + 1u] = floatBitsToUint(gNzGradient.y);
#endif
#ifdef TLAB_HAS_ST_GRADIENT
  for (uint k = 0u; k < 4u; ++k) record[TLAB_OFF_ST_GRADIENT + k] = floatBitsToUint(gStGradient[k]);
#endif
#ifdef TLAB_RECORD_QUADS
  for (uint q = 0u; q < TLAB_RECORD_QUADS; ++q)
    fragQuads[frag * TLAB_RECORD_QUADS + q] = uvec4(record[4u * q], record[4u * q + 1u], record[4u * q + 2u], record[4u * q + 3u]);
#else
  for (uint w = 0u; w < uint(TLAB_STRIDE); ++w) frags[fragWord(frag, w)] = record[w];
#endif
}
