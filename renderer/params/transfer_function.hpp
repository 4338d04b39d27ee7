#pragma once
// The transfer functions of mean-curvature shading and transparency (seed 002, Sec. 5.2):
//  - shading: a 1-D function of κ ∈ [−1, 1] whose value v ∈ [0, 1] scales the shaded colour by
//    2v (0.5 leaves it unchanged): Fig. 6(a) brightens convexities and darkens concavities,
//    Fig. 6(b) brightens curved and darkens flat surfaces;
//  - transparency: a 2-D opacity function of |κ| ∈ [0, 1] and depth ∈ [0, 1] (near → far):
//    Figs. 7(a)/(b), more transparency on flat and near surfaces, more opacity on curved and far
//    ones. The paper shows them only as pictures; the built-ins are control points read off them.
// A specification is a built-in name, inline control points or a PNG file (see parse()).
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tlab::render {

class CurvatureShadingFunction {
 public:
  static constexpr int kSamples = 256;
  // "fig6a" | "fig6b" | "points:κ=v,κ=v,..." (piecewise linear, κ ascending in [−1, 1], v in
  // [0, 1]) | a PNG path (its middle row, left = κ −1, right = κ +1, RGB). Throws
  // std::invalid_argument naming the problem.
  static CurvatureShadingFunction parse(const std::string& spec);
  static std::vector<std::string> builtins() { return {"fig6a", "fig6b"}; }
  glm::vec3 at(float kappa) const;                           // linear interpolation of the samples
  const std::vector<glm::vec3>& samples() const { return samples_; }  // κ = −1 .. +1

 private:
  std::vector<glm::vec3> samples_;
};

class CurvatureOpacityFunction {
 public:
  static constexpr int kSamples = 128;  // per axis
  // "fig7a" | "fig7b" | "grid:a,b,.../c,d,.../..." (rows from near to far, columns from |κ| = 0
  // to 1, values in [0, 1], bilinear; at least 2x2) | a PNG path (red channel; x = |κ| left to
  // right, y = depth from the bottom row (near) to the top row (far)).
  static CurvatureOpacityFunction parse(const std::string& spec);
  static std::vector<std::string> builtins() { return {"fig7a", "fig7b"}; }
  float at(float absKappa, float depth) const;  // bilinear interpolation of the samples
  const std::vector<float>& samples() const { return samples_; }  // row = depth, column = |κ|

 private:
  std::vector<float> samples_;
};

}  // namespace tlab::render
