/* tlab style
name = "silhouette-halo"
description = "constant opacity with a dark halo that fades along each surface away from its silhouette (neighbour links)"
properties = ["color"]
neighbors = true
iterations = 12

[[parameter]]
name = "alpha"
type = "float"
default = 0.25
range = [0.0, 1.0]
description = "opacity of every layer away from silhouettes"

[[parameter]]
name = "decay"
type = "float"
default = 0.1
range = [0.01, 1.0]
description = "how much the halo fades per linked step along the surface"

[[parameter]]
name = "strength"
type = "float"
default = 0.8
range = [0.0, 1.0]
description = "opacity and darkening of the halo at the silhouette"
*/
// Per-fragment stage. Iteration 0: every fragment starts outside the halo.
float initialValue(Fragment f) { return 0.0; }

// Iterations 1..N: a fragment with fewer than four linked neighbours lies where its surface ends
// in the image (a silhouette); elsewhere the halo spreads from the neighbours, fading by `decay`.
float iterate(Fragment f, Neighbors n) {
  if (n.count < 4) return 1.0;
  float h = f.value;
  for (int k = 0; k < n.count; ++k) h = max(h, n.value[k] - decay);
  return h;
}

// Compositing: front to back, the halo raising opacity and darkening the colour.
vec4 composite() {
  vec3 c = vec3(0.0);
  float T = 1.0;
  for (int i = 0; i < fragmentCount(); ++i) {
    Fragment f = fragment(i);
    float h = strength * f.value;
    float a = alpha + (1.0 - alpha) * h;
    c += T * a * mix(f.color.rgb, vec3(0.05), h);
    T *= 1.0 - a;
  }
  return vec4(c + T * background().rgb, 1.0);
}
