#version 450 core
// Silhouette edges as lines (Diepstraten Sec. 7: black line silhouettes).
layout(location = 0) in vec3 inPosition;
uniform mat4 uView;
uniform mat4 uProjection;
out float vEyeDepth;

void main() {
  vec4 viewPos = uView * vec4(inPosition, 1.0);
  vEyeDepth = -viewPos.z;
  gl_Position = uProjection * viewPos;
}
