#pragma once
// The alpha mask of dynamic transparency (Elmqvist et al., seed 004, Sec. V.4, Algs. 2-3, Fig. 2):
// a low-resolution grid (128 × 128 in the paper) over the image that holds, per cell, the
// opacity α given to distractor surfaces in front of a target: α_T on the target silhouette, a
// border of n cells whose α rises from α_0 to 1, and 1 elsewhere. The shape is the target's
// outline (the paper's choice), or a bounding circle or axis-aligned ellipse per target.
// Each cell also carries the eye-space depth of the target it belongs to, so that only surfaces
// in front of that target are made transparent.
//
// Pure CPU code on a small grid: the per-pixel target coverage comes from the GPU
// (compose/dynamic_coverage.comp) and the mask goes back as a buffer the compositor samples
// with bilinear filtering (Alg. 2 line 10).
#include <cstdint>
#include <string>
#include <vector>

namespace tlab::render {

enum class MaskShape { Outline, Circle, Ellipse };
MaskShape parseMaskShape(const std::string& word);  // outline | circle | ellipse

struct AlphaMaskSettings {
  int size = 128;             // cells per side (seed 004 Sec. V.4: 128 × 128)
  int border = 4;             // n: width of the gradient border in cells
  // The mask at the image's resolution: size = max(W, H) and the border n·size/128 cells wide, so
  // it covers the same share of the image as n cells of the paper's 128² grid, without the
  // grid's blocks (mask_size=0, the default; see atImageResolution).
  static AlphaMaskSettings atImageResolution(AlphaMaskSettings paper, int width, int height);
  float alphaTarget = 0.35f;  // α_T: opacity of surfaces in front of a target
  float alpha0 = 0.15f;       // α_0: opacity at the inner edge of the border gradient
  MaskShape shape = MaskShape::Outline;
};

// The targets each mask cell covers, at mask resolution. Cells are in GL order (row 0 = bottom).
struct TargetCoverage {
  int size = 0;
  std::vector<std::uint32_t> target;  // per cell: 1 + the object id of the farthest target, 0: none
  std::vector<float> depth;           // per cell: that target's eye-space depth

  // From per-pixel values (GL order, `pixelTarget` as above): a cell is covered when any of its
  // pixels is; it keeps the farthest target among them.
  static TargetCoverage fromPixels(int width, int height, const std::vector<std::uint32_t>& pixelTarget,
                                   const std::vector<float>& pixelDepth, int size);
};

struct AlphaMask {
  int size = 0;
  std::vector<float> alpha;  // per cell, GL order; 1 where no target is near
  std::vector<float> depth;  // per cell: the depth of the target behind it (0 where α = 1)
  float alphaAt(int x, int y) const { return alpha[std::size_t(y) * std::size_t(size) + std::size_t(x)]; }
};

// α_B of border layer i = 1..n (seed 004, Alg. 2 line 8: "increase the border alpha value from
// α_0 to 1.0"): α_B(i) = α_0 + (1 − α_0)(i − 1)/n; outside the border α = 1.
float borderAlpha(int layer, int border, float alpha0);

// `aspect`: image width / height, so circles and ellipses are round on screen.
AlphaMask buildAlphaMask(const TargetCoverage& coverage, const AlphaMaskSettings& settings, float aspect);

}  // namespace tlab::render
