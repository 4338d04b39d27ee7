// What both geometry passes of the bucketed k-buffer know about the current fragment: its key
// in Z (seed 002, Sec. 4.2: 16-bit depth as MSB, 16-bit shape id).
in vec3 vViewPosition;
flat in uint vObject;
flat in uint vComponent;
uniform int uWidth;
uniform int uShapeFromComponent;  // 0: shape id = object index, 1: connected component
uniform float uNear;
uniform float uFar;

uint currentPixel() { return uint(gl_FragCoord.y) * uint(uWidth) + uint(gl_FragCoord.x); }

uint currentShape() { return min(uShapeFromComponent == 1 ? vComponent : vObject, 0xFFFEu); }

uint currentDepth16() {
  float depth01 = clamp((-vViewPosition.z - uNear) / (uFar - uNear), 0.0, 1.0);
  return uint(round(depth01 * 65535.0));
}
