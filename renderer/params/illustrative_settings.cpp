#include "renderer/params/illustrative_settings.hpp"

#include <string>

#include <stdexcept>

#include "renderer/gpu/gl.hpp"

namespace tlab::render {

std::vector<ParamSpec> IllustrativeSettings::params() {
  return {
      ParamSpec::choice("shading", "lighting", {"lighting", "phong", "gooch"},
                        "lighting (the common `lighting` key), Phong with a headlight, or Gooch cool/warm (IRIS Sec. 5.1)"),
      ParamSpec::choice("two_sided", "on", {"on", "off"}, "back faces in the object's back colour"),
      ParamSpec::number("specular", 0.4, 0, 1, "Phong specular k_s; also the specular opacity α_spec"),
      ParamSpec::number("shininess", 32, 1, 1000, "Phong exponent"),
      ParamSpec::number("window_layers", 0, 0, 1000, "window transparency (IRIS Sec. 3.3) on the first N layers; 0: off"),
      ParamSpec::number("window_x", 0.5, 0, 1, "window centre, fraction of the width"),
      ParamSpec::number("window_y", 0.5, 0, 1, "window centre, fraction of the height from the top"),
      ParamSpec::number("window_radius", 0.25, 0, 2, "window radius, fraction of the height"),
      ParamSpec::number("window_falloff", 0.1, 0, 2, "smooth fall-off width beyond the radius, fraction of the height"),
      ParamSpec::number("window_opacity", 0.1, 0, 1, "opacity factor inside the window"),
      ParamSpec::choice("stripes", "off", {"off", "s", "t", "both", "lic"},
                        "adaptive pattern (IRIS Sec. 4.1): stripes along s, t, both (grid, Fig. 10b) or lic: noise "
                        "blurred along t (Fig. 10c)"),
      ParamSpec::number("stripe_period", 16, 1, 4096, "image-space stripe period in pixels (Eqs. 3-5 keep it within a factor 2)"),
      ParamSpec::number("stripe_width", 0.5, 0, 1, "stripe fraction of one period"),
      ParamSpec::number("stripe_strength", 0.8, 0, 1, "how much the pattern modulates opacity (α_tex)"),
      ParamSpec::number("stripe_darken", 0.3, 0, 1, "how much stripes darken the colour (c_tex)"),
      ParamSpec::choice("stripe_modulation", "multiply", {"multiply", "add"}, "α = α_view·α_tex or α_view + α_tex (IRIS Sec. 5.1)"),
      ParamSpec::choice("silhouettes", "off", {"off", "on"}, "Sobel silhouettes on per-layer normal and depth (IRIS Sec. 5.1)"),
      ParamSpec::number("silhouette_r", 0, 0, 1, "silhouette colour, red"),
      ParamSpec::number("silhouette_g", 0, 0, 1, "silhouette colour, green"),
      ParamSpec::number("silhouette_b", 0, 0, 1, "silhouette colour, blue"),
      ParamSpec::number("silhouette_threshold", 1.0, 0, 100, "Sobel strength where the fade to the silhouette colour starts"),
      ParamSpec::number("silhouette_softness", 1.0, 1e-6, 100, "Sobel strength range of the fade"),
  };
}

IllustrativeSettings IllustrativeSettings::from(const StyleParams& p, Opacity opacity) {
  IllustrativeSettings s;
  const auto has = [&](const char* key) { return p.values().count(key) != 0; };
  const auto num = [&](const char* key) { return static_cast<float>(p.number(key)); };
  s.opacity = opacity;
  if (has("alpha")) s.alpha = num("alpha");
  if (has("alpha_min")) s.alphaMin = num("alpha_min");
  if (has("alpha_max")) s.alphaMax = num("alpha_max");
  if (has("gamma")) s.gamma = num("gamma");
  s.shading = p.is("shading", "phong") ? Shading::Phong : p.is("shading", "gooch") ? Shading::Gooch : lightingShading(p);
  s.twoSided = p.is("two_sided", "on");
  s.specular = num("specular");
  s.shininess = num("shininess");
  s.windowLayers = static_cast<int>(p.number("window_layers"));
  s.windowCenter = {num("window_x"), num("window_y")};
  s.windowRadius = num("window_radius");
  s.windowFalloff = num("window_falloff");
  s.windowOpacity = num("window_opacity");
  const std::string& stripes = p.choice("stripes");
  s.stripes = stripes == "s" ? StripeS : stripes == "t" ? StripeT : stripes == "both" ? (StripeS | StripeT)
              : stripes == "lic" ? StripeNoise : 0u;
  s.stripePeriod = num("stripe_period");
  s.stripeWidth = num("stripe_width");
  s.stripeStrength = num("stripe_strength");
  s.stripeDarken = num("stripe_darken");
  s.stripeAdditive = p.is("stripe_modulation", "add");
  s.silhouettes = p.is("silhouettes", "on");
  s.silhouetteColor = {num("silhouette_r"), num("silhouette_g"), num("silhouette_b")};
  s.silhouetteThreshold = num("silhouette_threshold");
  s.silhouetteSoftness = num("silhouette_softness");
  if (s.alphaMin > s.alphaMax)
    throw std::invalid_argument("alpha_min (" + p.values().at("alpha_min") + ") must not exceed alpha_max (" +
                                p.values().at("alpha_max") + ")");
  return s;
}

IllustrativeSettings::Shading IllustrativeSettings::lightingShading(const StyleParams& p) {
  if (p.is("lighting", "none")) return Shading::Flat;
  return p.is("lighting", "pbr") ? Shading::Physical : Shading::Headlight;
}

IllustrativeSettings IllustrativeSettings::constant(float alpha, Shading shading) {
  IllustrativeSettings s;
  s.opacity = Opacity::Constant;
  s.alpha = alpha;
  s.shading = shading;
  return s;
}

gpu::ShaderDefines IllustrativeSettings::defines() const {
  return {{"TLAB_OPACITY_MODE", std::to_string(static_cast<int>(opacity))},
          {"TLAB_SHADING", std::to_string(static_cast<int>(shading))},
          {"TLAB_STRIPES", std::to_string(stripes)},
          {"TLAB_SILHOUETTES", silhouettes ? "1" : "0"}};
}

void IllustrativeSettings::setUniforms(const gpu::ShaderProgram& program, int width, int height) const {
  const auto f = [&](const char* name, float v) { glUniform1f(program.uniform(name), v); };
  const auto i = [&](const char* name, int v) { glUniform1i(program.uniform(name), v); };
  f("uAlpha", alpha);
  f("uAlphaMin", alphaMin);
  f("uAlphaMax", alphaMax);
  f("uGamma", gamma);
  i("uTwoSided", twoSided ? 1 : 0);
  f("uSpecular", specular);
  f("uShininess", shininess);
  // The window in GL pixel coordinates (row 0 = bottom).
  const float h = float(height);
  i("uWindowLayers", windowLayers);
  glUniform2f(program.uniform("uWindowCenter"), windowCenter.x * float(width), (1.0f - windowCenter.y) * h);
  f("uWindowRadius", windowRadius * h);
  f("uWindowFalloff", windowFalloff * h);
  f("uWindowOpacity", windowOpacity);
  f("uStripePeriod", stripePeriod);
  f("uStripeWidth", stripeWidth);
  f("uStripeStrength", stripeStrength);
  f("uStripeDarken", stripeDarken);
  i("uStripeAdditive", stripeAdditive ? 1 : 0);
  glUniform3fv(program.uniform("uSilhouetteColor"), 1, &silhouetteColor[0]);
  f("uSilhouetteThreshold", silhouetteThreshold);
  f("uSilhouetteSoftness", silhouetteSoftness);
}

}  // namespace tlab::render
