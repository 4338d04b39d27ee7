#pragma once
// The parameters of smart transparency (Carnecky Fig. 9), read once from the style parameters.
#include <string>

#include "renderer/params/style_params.hpp"

namespace tlab::render {

enum class DiffusionScheme { Explicit, Substep, Implicit };

struct SmartSettings {
  int iterations = 20;            // n of Sec. 5.4
  double lambdaAlpha = 1.0;       // λα of Eq. 8
  double lambdaBeta = 0.05;       // λβ of Eq. 9
  double lambdaGamma = 0.1;       // λγ of Eq. 9
  double s = 0.3;                 // s of Eqs. 4-5
  bool adaptiveAlpha = false;     // Eq. 5 instead of Eq. 4
  int modifier = 1;               // 0 none, 1 exp (Eq. 10), 2 pow (Eq. 11)
  double p = 3.0;                 // p of Eqs. 10-11
  bool spreadByMax = true;        // Eq. 9 (max) or Eq. 8 (diffusion) for β and γ
  bool halos = true;              // γ field
  bool silhouettes = true;        // β field
  double wz = 1.0, wn = 1.0;      // Eq. 3
  bool normalizedLaplacian = true;  // Eq. 8's Laplacian: mean of the neighbours − α, or their sum
  DiffusionScheme scheme = DiffusionScheme::Explicit;
  int jacobiSweeps = 10;          // per implicit step

  // The largest λα one explicit step of Eq. 8 takes without losing the maximum principle.
  double explicitBound() const;
  // Whether the α field can change at all: not when every fragment starts at the same α (Eq. 4),
  // since a uniform field is a fixed point of Eq. 8 with Neumann boundaries.
  bool diffusesAlpha() const { return iterations > 0 && lambdaAlpha > 0 && adaptiveAlpha; }
  // Dispatches of the α diffusion per step: Jacobi sweeps (implicit), 1 (explicit) or the
  // sub-steps; 0 when α cannot change.
  int alphaDispatchesPerStep() const;

  static SmartSettings from(const StyleParams& params);
};

// The explicit scheme of Eq. 8 keeps the maximum principle (no oscillation, values stay in
// [0, 1]) iff every fragment's weight of its neighbours sums to at most 1: λ ≤ 1 with the
// normalised Laplacian (mean of the neighbours − α_i), λ ≤ 1/4 with the sum Σ_j (α_j − α_i) on
// the 4-neighbour graph.
constexpr double kExplicitStableLambdaNormalized = 1.0;
constexpr double kExplicitStableLambdaSum = 0.25;

// Sub-steps needed so that each explicit step has λ/m ≤ bound.
int substepsFor(double lambda, double bound);

// solver=auto: explicit up to the bound, sub-stepped up to kMaxAutoSubsteps sub-steps, and
// implicit beyond, where sub-stepping would cost more passes than the Jacobi sweeps.
constexpr int kMaxAutoSubsteps = 8;
DiffusionScheme automaticScheme(double lambda, double bound);

}  // namespace tlab::render
