#pragma once
// The local illustrative shading of IRIS (Hummel et al. 2010, Secs. 3-5): view-dependent opacity
// (angle, Sec. 3.1; normal variation, Eq. 2), window transparency (Sec. 3.3), two-sided
// colouring, Phong or Gooch shading, adaptive stripe patterns (Sec. 4.1, Eqs. 3-5) and Sobel
// silhouettes (Sec. 5.1). One set of settings drives both ways of compositing: the illustration
// buffer (compose/illustrative_compose.comp) and depth peeling (peel/peel_layer.frag); the
// GLSL side is frame/illustrative_shading.glsl.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/gpu/shader_program.hpp"
#include "renderer/params/style_params.hpp"

namespace tlab::render {

struct IllustrativeSettings {
  enum class Opacity { Constant, Angle, NormalVariation };
  enum class Shading { Flat, Headlight, Phong, Gooch, Physical };
  enum StripeAxis : std::uint32_t { StripeS = 1u, StripeT = 2u, StripeNoise = 4u };  // noise: IRIS Fig. 10c

  Opacity opacity = Opacity::Constant;
  float alpha = 0.25f;                    // Constant
  float alphaMin = 0.1f, alphaMax = 0.9f;  // [α_min, α_max] of IRIS Sec. 3.2
  float gamma = 0.5f;                      // γ of IRIS Eq. 2

  Shading shading = Shading::Headlight;
  bool twoSided = true;   // back faces in the object's back colour
  float specular = 0.4f;  // Phong k_s (also α_spec, IRIS Sec. 5.1 "Combination")
  float shininess = 32.0f;

  int windowLayers = 0;                // window transparency on the first N layers (0: off)
  glm::vec2 windowCenter{0.5f, 0.5f};  // image fractions, y from the top
  float windowRadius = 0.25f;          // fraction of the image height
  float windowFalloff = 0.1f;          // fraction of the image height
  float windowOpacity = 0.1f;          // opacity factor at the centre

  std::uint32_t stripes = 0;  // StripeAxis bits: s, t, both (the grid of Fig. 10b) or noise alone
  float stripePeriod = 16.0f; // requested image-space period in pixels
  float stripeWidth = 0.5f;   // stripe fraction of one period
  float stripeStrength = 0.8f;
  float stripeDarken = 0.3f;
  bool stripeAdditive = false;

  bool silhouettes = false;
  glm::vec3 silhouetteColor{0.0f};
  float silhouetteThreshold = 1.0f, silhouetteSoftness = 1.0f;

  // Parameters shared by the IRIS styles (everything but the opacity mode and its α values).
  static std::vector<ParamSpec> params();
  // Reads params() and the opacity values present in `p` (alpha, alpha_min, alpha_max, gamma).
  static IllustrativeSettings from(const StyleParams& p, Opacity opacity);
  // The common `lighting` choice as a shading: none → Flat, headlight, pbr → Physical.
  static Shading lightingShading(const StyleParams& p);
  // The `constant` style: one α, the common `lighting` choice, nothing else.
  static IllustrativeSettings constant(float alpha, Shading shading);

  // Sets every uniform of frame/illustrative_shading.glsl and frame/sobel_silhouette.glsl.
  void setUniforms(const gpu::ShaderProgram& program, int width, int height) const;
  // The modes the shaders branch on (opacity, shading, stripes, silhouettes) as defines, compiled
  // into a program instead of read from uniforms: llvmpipe runs every side of an `if` under a lane
  // mask, so with uniforms every fragment paid for each mode it did not use (issue #29).
  // setUniforms sets the rest.
  gpu::ShaderDefines defines() const;
};

}  // namespace tlab::render
