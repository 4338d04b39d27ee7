#version 450 core
// Peel stage of the depth-peeling loop (IRIS Sec. 5.1, after Bavoil and Myers): keeps only
// fragments behind the previous layer's depth; the depth test then selects the nearest of them.
// The layer's fragment is fully shaded here (frame/illustrative_shading.glsl) with dFdx/dFdy for
// the derivatives of IRIS Eqs. 2-4 (the illustration buffer stores the same dFdx/dFdy at fill
// time); its view normal and eye depth go to a second target for the
// Sobel silhouettes of the blend stage.
#include "frame/fragment_layout.glsl"
#include "frame/surface_shading.glsl"
#include "frame/illustrative_shading.glsl"
in vec3 vViewPosition;
in vec3 vViewNormal;
in vec2 vST;
flat in uint vObject;
flat in uint vComponent;
layout(location = 0) out vec4 outColor;         // (c, α) of this layer
layout(location = 1) out vec4 outNormalDepth;   // (view normal, eye depth); w = 0: no fragment,
                                                // w < 0: context geometry (the silhouette mask)
uniform sampler2D uPreviousDepth;
uniform int uLayer;

void main() {
  // Derivatives first, in uniform control flow.
  // The same definition as buffer/fragment_record.glsl (captureDerivatives).
  vec3 n = normalize(vViewNormal);
  vec2 nzGradient = vec2(dFdx(n.z), dFdy(n.z));
  vec4 stGradient = vec4(dFdx(vST.x), dFdy(vST.x), dFdx(vST.y), dFdy(vST.y));
  if (uLayer > 0 && gl_FragCoord.z <= texelFetch(uPreviousDepth, ivec2(gl_FragCoord.xy), 0).r) discard;
  SurfaceSample s;
  s.viewPosition = vViewPosition;
  s.normal = n;
  s.frontFacing = gl_FrontFacing;
  s.object = vObject;
  s.layer = uint(uLayer);
  s.pixel = gl_FragCoord.xy;
  s.st = vST;
  s.nzGradient = nzGradient;
  s.stGradient = stGradient;
  outColor = illustrate(s);
  outNormalDepth = vec4(n, isContext(vObject) ? vViewPosition.z : -vViewPosition.z);
}
