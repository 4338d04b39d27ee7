#pragma once
// Images from another renderer are stimuli only when they show tlab's scene from tlab's camera:
// tlab's own coverage of the cell (pixels with at least one fragment) is compared with the
// image's non-background pixels by intersection over union, and a poor overlap is explained
// (vertical flip, field of view, aspect, a shifted camera) before any participant sees a mark.
#include <cstdint>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "renderer/pipeline/renderer.hpp"

namespace tlab::stimuli {

// The overlap that admits an image (issue #28).
constexpr double kMinimumAlignmentIoU = 0.98;

// A w×h mask, row 0 = top.
struct CoverageMask {
  int width = 0, height = 0;
  std::vector<std::uint8_t> covered;
  std::size_t count() const;
};

// The image's non-background pixels: where it has transparent pixels, those with alpha > 0.5;
// else those whose colour differs by more than 0.05 in a channel from the background, taken as
// the colour most of the four corners share (the first corner when they all differ).
CoverageMask imageCoverage(const core::Image& image);
// tlab's coverage from per-pixel fragment counts (Renderer::layerCounts, row 0 = top).
CoverageMask coverageFromCounts(const std::vector<std::uint16_t>& counts, int width, int height);

double intersectionOverUnion(const CoverageMask& a, const CoverageMask& b);

struct AlignmentResult {
  double iou = 0.0;
  bool aligned = false;       // iou >= kMinimumAlignmentIoU
  std::string likelyCause;    // empty when aligned
};

// Compares tlab's coverage with the image's; both must have the same size.
AlignmentResult compareCoverage(const CoverageMask& tlab, const CoverageMask& theirs);

// An image from another renderer for a stimulus of width×height, as read (its alpha kept for the
// coverage); throws std::runtime_error naming the file when it is no PNG or has another size.
core::Image readExternalImage(const std::string& path, int width, int height);
// The image as shown: over nothing, so opaque.
core::Image opaque(core::Image image);
// tlab's coverage of the renderer's scene from `camera` at the image's size (a GL context must be
// current) compared with the image's.
AlignmentResult alignWithView(render::Renderer& renderer, const render::Camera& camera, const core::Image& image);
// "IMAGE: IoU 0.7112 with tlab's coverage of WHAT (below 0.98): the image does not show tlab's
// view; likely cause: ..." — the one line that refuses a misaligned image.
std::string misalignmentMessage(const std::string& image, const std::string& what, const AlignmentResult& result);
// The IoU as the messages print it (4 significant digits).
std::string iouText(double iou);

}  // namespace tlab::stimuli
