// Physically based shading for `lighting=pbr` (Murray et al., seed 002 Sec. 4.2: "the BRDF
// proposed by Disney [BS12] for direct illumination and Image-Based Lighting to approximate
// indirect illumination"). A dielectric, roughness 0.5, in a fixed studio rig given in view space
// (so every style and every view sees the same lighting, like the headlight):
//  - direct light: one key light above left of the viewer, Burley's diffuse (Disney 2012, Eq. of
//    Sec. 5.3) plus a GGX / Trowbridge-Reitz specular lobe with Smith-GGX visibility and Schlick
//    Fresnel (F0 = 0.04);
//  - indirect light: a procedural sky (zenith blue, bright horizon, warm ground) as the
//    environment map: diffuse irradiance of that gradient in closed form (hemisphere lighting),
//    specular as the sky radiance along the reflection direction, widened toward the irradiance by
//    the roughness, times Karis' analytic environment-BRDF fit (split sum, 2014).
// Included by frame/surface_shading.glsl; pure functions of (base colour, n, v).
const float kPbrPi = 3.14159265358979;
const float kPbrRoughness = 0.5;
const vec3 kPbrKeyDirection = vec3(-0.4, 0.8, 0.6);  // normalised where used
const float kPbrKeyIntensity = 2.2;
const vec3 kSkyZenith = vec3(0.32, 0.46, 0.75), kSkyHorizon = vec3(0.85, 0.88, 0.92), kSkyGround = vec3(0.36, 0.27, 0.18);

// The environment: radiance from direction d (view space, y up).
vec3 skyRadiance(vec3 d) {
  float y = clamp(d.y, -1.0, 1.0);
  return y >= 0.0 ? mix(kSkyHorizon, kSkyZenith, sqrt(y)) : mix(kSkyHorizon, kSkyGround, sqrt(-y));
}

// Cosine-weighted irradiance / π of the sky around n: the two-hemisphere closed form.
vec3 skyIrradiance(vec3 n) {
  vec3 upper = 0.5 * (kSkyHorizon + kSkyZenith), lower = 0.5 * (kSkyHorizon + kSkyGround);
  return mix(lower, upper, 0.5 + 0.5 * n.y);
}

// Burley 2012: f_d = (base/π)(1 + (F_D90 − 1)(1 − n·l)^5)(1 + (F_D90 − 1)(1 − n·v)^5),
// F_D90 = 0.5 + 2·roughness·(l·h)².
float burleyDiffuse(float nl, float nv, float lh) {
  float fd90 = 0.5 + 2.0 * kPbrRoughness * lh * lh;
  return (1.0 + (fd90 - 1.0) * pow(1.0 - nl, 5.0)) * (1.0 + (fd90 - 1.0) * pow(1.0 - nv, 5.0)) / kPbrPi;
}

// GGX normal distribution, Smith-GGX height-correlated visibility, Schlick Fresnel (a = roughness²).
float ggxSpecular(float nl, float nv, float nh, float vh) {
  float a = kPbrRoughness * kPbrRoughness, a2 = a * a;
  float d = nh * nh * (a2 - 1.0) + 1.0;
  float D = a2 / (kPbrPi * d * d);
  float visibility = 0.5 / max(nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2), 1e-6);
  float F = 0.04 + 0.96 * pow(1.0 - vh, 5.0);
  return D * visibility * F;
}

// Karis 2014, the analytic fit of the split-sum environment BRDF: (scale, bias) on F0.
vec2 environmentBrdf(float nv) {
  const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022), c1 = vec4(1.0, 0.0425, 1.04, -0.04);
  vec4 r = kPbrRoughness * c0 + c1;
  float a004 = min(r.x * r.x, exp2(-9.28 * nv)) * r.x + r.y;
  return vec2(-1.04, 1.04) * a004 + r.zw;
}

// Outgoing radiance toward the eye for base colour `base`, unit normal n facing the viewer, unit v.
vec3 shadePhysical(vec3 base, vec3 n, vec3 v) {
  vec3 l = normalize(kPbrKeyDirection), h = normalize(l + v);
  float nl = max(dot(n, l), 0.0), nv = max(dot(n, v), 1e-4), nh = max(dot(n, h), 0.0), lh = max(dot(l, h), 0.0);
  vec3 direct = (base * burleyDiffuse(nl, nv, lh) + vec3(ggxSpecular(nl, nv, nh, lh))) * kPbrKeyIntensity * nl;
  vec3 r = reflect(-v, n);
  vec3 prefiltered = mix(skyRadiance(r), skyIrradiance(r), kPbrRoughness);
  vec2 brdf = environmentBrdf(nv);
  vec3 indirect = base * skyIrradiance(n) + prefiltered * (0.04 * brdf.x + brdf.y);
  return clamp(direct + indirect, 0.0, 1.0);
}
