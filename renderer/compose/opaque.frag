#version 450 core
// Style `opaque`: the nearest surface by the ordinary z-buffer, shaded; no fragment lists.
#include "buffer/fragment_layout.glsl"
#include "buffer/surface_shading.glsl"
in vec3 vViewPosition;
in vec3 vViewNormal;
in vec2 vST;
flat in uint vObject;
flat in uint vComponent;
layout(location = 0) out vec4 outColor;

void main() {
  outColor = vec4(shadeSurface(vObject, gl_FrontFacing, vViewNormal, vViewPosition), 1.0);
}
