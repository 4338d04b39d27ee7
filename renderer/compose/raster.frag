#version 450 core
// Styles `opaque` (z-buffered nearest surface) and `unsorted` (plain blending with uAlpha): the
// surface colour straight into the colour target; no fragment lists.
#include "frame/fragment_layout.glsl"
#include "frame/surface_shading.glsl"
in vec3 vViewPosition;
in vec3 vViewNormal;
in vec2 vST;
flat in uint vObject;
flat in uint vComponent;
layout(location = 0) out vec4 outColor;
uniform float uAlpha;

void main() {
  outColor = vec4(shadeSurface(vObject, gl_FrontFacing, vViewNormal, vViewPosition), uAlpha);
}
