/* tlab style
name = "depth-tinted-alpha"
description = "opacity grows with depth: near layers faint, far layers strong, tinted towards a far colour"
properties = ["color"]

[[parameter]]
name = "alpha_near"
type = "float"
default = 0.1
range = [0.0, 1.0]
description = "opacity of a layer at the front of the scene"

[[parameter]]
name = "alpha_far"
type = "float"
default = 0.6
range = [0.0, 1.0]
description = "opacity of a layer at the back of the scene"

[[parameter]]
name = "tint"
type = "float"
default = 0.5
range = [0.0, 1.0]
description = "how far a back layer's colour moves towards blue"
*/
vec4 composite() {
  vec3 c = vec3(0.0);
  float T = 1.0;
  for (int i = 0; i < fragmentCount(); ++i) {
    Fragment f = fragment(i);
    // 0 at the near clipping plane, 1 at the far one (tlab fits both to the scene's bounds).
    float d = clamp((f.depth - nearPlane()) / (farPlane() - nearPlane()), 0.0, 1.0);
    float a = mix(alpha_near, alpha_far, d);
    vec3 colour = mix(f.color.rgb, vec3(0.2, 0.35, 0.9), tint * d);
    c += T * a * colour;
    T *= 1.0 - a;
  }
  return vec4(c + T * background().rgb, 1.0);
}
