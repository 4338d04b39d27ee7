// Writes the properties of the current fragment into record `frag` of `frags` (the style's
// FragmentLayout decides which exist). Included by the fill shaders.
in vec3 vViewPosition;
in vec3 vViewNormal;
in vec2 vST;
flat in uint vObject;
flat in uint vComponent;

uniform uint uPrimitiveBase;

// Screen-space derivatives must be taken in uniform control flow: call this first in main().
vec2 gDepthGradient;
void captureDerivatives() {
  float depth = -vViewPosition.z;
  gDepthGradient = vec2(dFdx(depth), dFdy(depth));
}

void writeFragmentRecord(uint frag) {
  float depth = -vViewPosition.z;  // eye-space distance along the view axis
  frags[fragWord(frag, OFF_DEPTH)] = floatBitsToUint(depth);
  frags[fragWord(frag, OFF_PRIM)] = uPrimitiveBase + uint(gl_PrimitiveID);
#ifdef TLAB_HAS_COLOR
  frags[fragWord(frag, TLAB_OFF_COLOR)] =
      packUnorm4x8(vec4(shadeSurface(vObject, gl_FrontFacing, vViewNormal, vViewPosition), 1.0));
#endif
#ifdef TLAB_HAS_NORMAL
  frags[fragWord(frag, TLAB_OFF_NORMAL)] = encodeNormal(normalize(vViewNormal));
#endif
#ifdef TLAB_HAS_DEPTH_GRADIENT
  frags[fragWord(frag, TLAB_OFF_DEPTH_GRADIENT) + 0u] = floatBitsToUint(gDepthGradient.x);
  frags[fragWord(frag, TLAB_OFF_DEPTH_GRADIENT) + 1u] = floatBitsToUint(gDepthGradient.y);
#endif
#ifdef TLAB_HAS_IDS
  // object id (16 bits) | component id (15 bits) | front-facing flag (bit 31)
  frags[fragWord(frag, TLAB_OFF_IDS)] =
      (vObject & 0xFFFFu) | ((vComponent & 0x7FFFu) << 16) | (gl_FrontFacing ? 0x80000000u : 0u);
#endif
#ifdef TLAB_HAS_ST
  frags[fragWord(frag, TLAB_OFF_ST) + 0u] = floatBitsToUint(vST.x);
  frags[fragWord(frag, TLAB_OFF_ST) + 1u] = floatBitsToUint(vST.y);
#endif
}
