/* tlab style
name = "constant-file"
description = "the built-in constant as a file: every layer with opacity alpha, front to back"
properties = ["color"]

[[parameter]]
name = "alpha"
type = "float"
default = 0.25
range = [0.0, 1.0]
description = "opacity of every layer"
*/
// Front-to-back blending (Carnecky Eq. 4): c <- c + T*alpha*c_i, T <- T*(1 - alpha).
vec4 composite() {
  vec3 c = vec3(0.0);
  float T = 1.0;  // remaining transmittance
  for (int i = 0; i < fragmentCount(); ++i) {
    Fragment f = fragment(i);
    c += T * alpha * f.color.rgb;
    T *= 1.0 - alpha;
  }
  return vec4(c + T * background().rgb, 1.0);
}
