// Silhouette strength by a Sobel filter on one layer's depth and normal images (IRIS Sec. 5.1,
// after Saito and Takahashi): the caller gathers the 3x3 neighbourhood of the same layer, row by
// row from the bottom (index 4 is the centre). A neighbour without a fragment of this layer
// counts as twice as far with a zero normal, so every layer's outline is an edge. As in IRIS, a
// mask keeps silhouettes off context geometry: no silhouette where any of the nine samples is
// context (depth < 0 marks a context sample).
#define SILHOUETTES TLAB_SILHOUETTES  // 0 or 1, compiled in (IllustrativeSettings::defines)
uniform vec3 uSilhouetteColor;
uniform float uSilhouetteThreshold;
uniform float uSilhouetteSoftness;

const float kSobelX[9] = float[9](-1.0, 0.0, 1.0, -2.0, 0.0, 2.0, -1.0, 0.0, 1.0);
const float kSobelY[9] = float[9](-1.0, -2.0, -1.0, 0.0, 0.0, 0.0, 1.0, 2.0, 1.0);

// depth: eye-space depth (0: no fragment, negative: context); normal: unit view-space normal.
float sobelStrength(float depth[9], vec3 normal[9]) {
  for (int k = 0; k < 9; ++k)
    if (depth[k] < 0.0) return 0.0;
  float zc = depth[4];
  vec2 gz = vec2(0.0);
  vec3 gnx = vec3(0.0), gny = vec3(0.0);
  for (int k = 0; k < 9; ++k) {
    bool present = depth[k] > 0.0;
    float z = (present ? depth[k] : 2.0 * zc) / zc;  // relative depth: scale-free
    vec3 n = present ? normal[k] : vec3(0.0);
    gz += vec2(kSobelX[k], kSobelY[k]) * z;
    gnx += kSobelX[k] * n;
    gny += kSobelY[k] * n;
  }
  return length(gz) + sqrt(dot(gnx, gnx) + dot(gny, gny));
}

// Fades (c, α) into the silhouette colour (opaque) with the silhouette strength.
vec4 applySilhouette(vec4 ca, float strength) {
  if (SILHOUETTES == 0) return ca;
  float f = smoothstep(uSilhouetteThreshold, uSilhouetteThreshold + uSilhouetteSoftness, strength);
  return vec4(mix(ca.rgb, uSilhouetteColor, f), mix(ca.a, 1.0, f));
}
