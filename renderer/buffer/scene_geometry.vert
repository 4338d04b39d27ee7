#version 450 core
// Transforms scene vertices to view space for every rasterizing pass.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inST;
layout(location = 3) in uint inObject;
layout(location = 4) in uint inComponent;

uniform mat4 uView;
uniform mat4 uProjection;

out vec3 vViewPosition;
out vec3 vViewNormal;
out vec2 vST;
flat out uint vObject;
flat out uint vComponent;

void main() {
  vec4 viewPos = uView * vec4(inPosition, 1.0);
  vViewPosition = viewPos.xyz;
  vViewNormal = mat3(uView) * inNormal;  // the view matrix is a rigid motion
  vST = inST;
  vObject = inObject;
  vComponent = inComponent;
  gl_Position = uProjection * viewPos;
}
