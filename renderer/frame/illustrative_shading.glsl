// The local illustrative shading of IRIS (Hummel et al. 2010, Secs. 3-5), shared by the
// illustration-buffer compositor and the depth-peeling layer shader: each caller fills a
// SurfaceSample (with its own screen-space derivatives: neighbour links or dFdx/dFdy) and gets the
// fragment's (c, α). Needs frame/surface_shading.glsl (the object table) included first.
// Objects with Role::Opaque are IRIS's context geometry (Sec. 5): shaded alike, always opaque,
// without view-dependent opacity, stripes or window, and masked out of the silhouettes.
const float kPi = 3.14159265358979;

struct SurfaceSample {
  vec3 viewPosition;  // view space, the eye at the origin
  vec3 normal;        // interpolated unit normal (outward), view space
  bool frontFacing;
  uint object;
  uint layer;         // 0 = nearest
  vec2 pixel;         // GL window coordinates of the pixel centre
  vec2 st;            // surface parameters
  vec2 nzGradient;    // (∂n_z/∂i, ∂n_z/∂j)
  vec4 stGradient;    // (∂s/∂i, ∂s/∂j, ∂t/∂i, ∂t/∂j)
};

// The modes below are compiled in, not uniforms (IllustrativeSettings::defines): llvmpipe runs
// every side of an `if` under a lane mask, so with uniforms each fragment paid for every mode
// (issue #29). TLAB_OPACITY_MODE: 0 constant, 1 angle, 2 normal variation.
#define OPACITY_MODE TLAB_OPACITY_MODE
uniform float uAlpha;
uniform float uAlphaMin;
uniform float uAlphaMax;
uniform float uGamma;
#define SHADING_MODEL TLAB_SHADING  // 0 flat, 1 headlight, 2 Phong, 3 Gooch, 4 physically based
uniform int uTwoSided;
uniform float uSpecular;
uniform float uShininess;
uniform int uWindowLayers;
uniform vec2 uWindowCenter;
uniform float uWindowRadius;
uniform float uWindowFalloff;
uniform float uWindowOpacity;
#define STRIPE_AXES TLAB_STRIPES  // bit 0: s, bit 1: t, bit 2: the LIC-like noise
uniform float uStripePeriod;
uniform float uStripeWidth;
uniform float uStripeStrength;
uniform float uStripeDarken;
uniform int uStripeAdditive;

bool isContext(uint object) { return (objects[object].info.x & 2u) != 0u; }  // Role::Opaque

// α_view mapped to [α_min, α_max] (IRIS Sec. 3.2: α = (1 − α_view)·α_min + α_view·α_max).
float viewOpacity(SurfaceSample s) {
  if (OPACITY_MODE == 0) return uAlpha;
  float a;
  if (OPACITY_MODE == 1) {
    // IRIS Sec. 3.1: α_view = (2/π)·arccos|n·v|, v the unit vector towards the eye.
    float c = clamp(abs(dot(normalize(s.normal), normalize(-s.viewPosition))), 0.0, 1.0);
    a = 2.0 / kPi * acos(c);
  } else {
    // IRIS Eq. 2: α_view = ((∂n_z/∂i)² + (∂n_z/∂j)²)^(γ/2), clamped to [0, 1] before γ.
    float g = clamp(length(s.nzGradient), 0.0, 1.0);
    a = uGamma == 0.0 ? 1.0 : pow(g, uGamma);
  }
  return (1.0 - a) * uAlphaMin + a * uAlphaMax;
}

// Window transparency (IRIS Sec. 3.3): the opacity factor falls smoothly to uWindowOpacity
// inside a disc around a screen point, on the first uWindowLayers layers.
float windowFactor(SurfaceSample s) {
  if (int(s.layer) >= uWindowLayers) return 1.0;
  float inside = 1.0 - smoothstep(uWindowRadius, uWindowRadius + max(uWindowFalloff, 1e-6), distance(s.pixel, uWindowCenter));
  return mix(1.0, uWindowOpacity, inside);
}

// A hash of an integer lattice point to [0, 1) (deterministic on every GPU).
float latticeNoise(ivec2 c) {
  uint h = uint(c.x) * 0x8da6b343u ^ uint(c.y) * 0xd8163841u;
  h = (h ^ (h >> 15)) * 0x2c1b3c6du;
  h = (h ^ (h >> 12)) * 0x297a2d39u;
  return float((h ^ (h >> 15)) & 0xFFFFu) / 65536.0;
}

// IRIS Fig. 10c: "noise blurred in t-direction" for a LIC-like look — 8 noise cells per period
// across s, each a smooth (cubic) ramp between lattice values along t, so a streak runs a whole
// period along t.
float licPattern(vec2 u) {
  int i = int(floor(u.x * 8.0));
  float v = u.y, f = fract(v);
  int j = int(floor(v));
  float w = f * f * (3.0 - 2.0 * f);
  return mix(latticeNoise(ivec2(i, j)), latticeNoise(ivec2(i, j + 1)), w);
}

// The pattern P(s, t) over the unit period: stripes across s, across t, or both (a grid), or
// the LIC-like noise.
float stripePattern(vec2 u) {
  if ((STRIPE_AXES & 4) != 0) return licPattern(u);
  float p = 0.0;
  if ((STRIPE_AXES & 1) != 0 && fract(u.x) < uStripeWidth) p = 1.0;
  if ((STRIPE_AXES & 2) != 0 && fract(u.y) < uStripeWidth) p = 1.0;
  return p;
}

// P̂_{l_s,l_t}(s, t) = P(s·2^−l_s, t·2^−l_t) (IRIS Sec. 4.1).
float levelPattern(vec2 st, vec2 level) { return stripePattern(st * exp2(-level)); }

// The adaptive pattern c(s, t) of IRIS Eq. 5. λ_s, λ_t (Eqs. 3-4) are measured in units of the
// requested period, so one pattern period covers uStripePeriod pixels at l = log2 λ exactly and
// between half and twice that at the neighbouring integer levels.
float adaptivePattern(vec2 st, vec4 g) {
  vec2 lambda = vec2(length(g.xy), length(g.zw)) * uStripePeriod;  // Eqs. 3-4
  vec2 l = log2(max(lambda, vec2(1e-30)));
  vec2 lo = floor(l), f = l - lo;                                   // l̃_s, l̃_t
  vec2 hi = lo + 1.0;
  return (1.0 - f.x) * ((1.0 - f.y) * levelPattern(st, vec2(lo.x, lo.y)) + f.y * levelPattern(st, vec2(lo.x, hi.y))) +
         f.x * ((1.0 - f.y) * levelPattern(st, vec2(hi.x, lo.y)) + f.y * levelPattern(st, vec2(hi.x, hi.y)));  // Eq. 5
}

// The surface colour before any transparency: front/back colour (two-sided), then flat,
// headlight diffuse, Phong (diffuse + separate specular) or Gooch cool/warm tones.
struct Shaded {
  vec3 diffuse;
  vec3 specular;
  float specularAlpha;
};

Shaded shadeIllustrative(SurfaceSample s) {
  bool back = uTwoSided != 0 && !s.frontFacing;
  vec3 base = back ? objects[s.object].backColor.rgb : objects[s.object].frontColor.rgb;
  vec3 v = normalize(-s.viewPosition);
  vec3 n = normalize(s.normal);
  if (dot(n, v) < 0.0) n = -n;  // two-sided lighting
  Shaded r = Shaded(base, vec3(0.0), 0.0);
  if (SHADING_MODEL == 1) {
    r.diffuse = base * (0.25 + 0.75 * dot(n, v));  // as frame/surface_shading.glsl
  } else if (SHADING_MODEL == 2) {
    // Phong with a headlight (l = v): ambient + diffuse, and a separate specular term.
    r.diffuse = base * (0.2 + 0.8 * dot(n, v));
    float spec = uSpecular * pow(max(dot(reflect(-v, n), v), 0.0), uShininess);
    r.specular = vec3(spec);
    r.specularAlpha = spec;
  } else if (SHADING_MODEL == 3) {
    // Gooch et al. 1998 tones: k_cool = (0, 0, 0.4) + 0.2·k_d, k_warm = (0.4, 0.4, 0) + 0.6·k_d,
    // blended by (1 + n·l)/2 with a key light above and to the left of the viewer.
    vec3 l = normalize(vec3(-0.4, 0.8, 0.6));
    float t = 0.5 * (1.0 + dot(n, l));
    vec3 cool = vec3(0.0, 0.0, 0.4) + 0.2 * base, warm = vec3(0.4, 0.4, 0.0) + 0.6 * base;
    r.diffuse = t * warm + (1.0 - t) * cool;
  } else if (SHADING_MODEL == 4) {
    r.diffuse = shadePhysical(base, n, v);  // frame/physical_shading.glsl
  }
  return r;
}

// IRIS Sec. 5.1, "Combination": α = α_view·α_tex + α_spec (multiplicative) or
// α_view + α_tex + α_spec (additive); c = c_diffuse·c_tex + c_spec; then the window factor.
vec4 illustrate(SurfaceSample s) {
  Shaded shaded = shadeIllustrative(s);
  if (isContext(s.object)) return vec4(clamp(shaded.diffuse + shaded.specular, 0.0, 1.0), 1.0);
  float alphaView = viewOpacity(s);
  float alpha = alphaView;
  vec3 ctex = vec3(1.0);
  if (STRIPE_AXES != 0) {
    float c = adaptivePattern(s.st, s.stGradient);
    ctex = vec3(1.0 - uStripeDarken * c);
    alpha = uStripeAdditive != 0 ? alphaView + uStripeStrength * c : alphaView * (1.0 - uStripeStrength * (1.0 - c));
  }
  alpha = clamp(alpha + shaded.specularAlpha, 0.0, 1.0) * windowFactor(s);
  return vec4(clamp(shaded.diffuse * ctex + shaded.specular, 0.0, 1.0), alpha);
}
