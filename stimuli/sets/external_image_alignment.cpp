#include "stimuli/sets/external_image_alignment.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "core/png_file.hpp"

namespace tlab::stimuli {

namespace {

bool sameColour(const glm::vec4& a, const glm::vec4& b) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(a[c] - b[c]) > 0.05f) return false;
  return true;
}

glm::vec4 backgroundOf(const core::Image& image) {
  const std::array<glm::vec4, 4> corners = {image.at(0, 0), image.at(image.width - 1, 0), image.at(0, image.height - 1),
                                            image.at(image.width - 1, image.height - 1)};
  for (const auto& c : corners)
    if (std::count_if(corners.begin(), corners.end(), [&](const glm::vec4& d) { return sameColour(c, d); }) >= 2) return c;
  return corners[0];
}

// The bounding box and centroid of a mask, in pixels.
struct Extent {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0, cx = 0, cy = 0;
  double width() const { return x1 - x0 + 1; }
  double height() const { return y1 - y0 + 1; }
};

// The mask moved by (dx, dy) pixels; what leaves the image is lost.
CoverageMask translated(const CoverageMask& m, int dx, int dy) {
  CoverageMask t{m.width, m.height, std::vector<std::uint8_t>(m.covered.size(), 0)};
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      const int u = x + dx, v = y + dy;
      if (u >= 0 && v >= 0 && u < m.width && v < m.height) t.covered[std::size_t(v) * m.width + u] = m.covered[std::size_t(y) * m.width + x];
    }
  return t;
}

// How far `b` lies from `a` along one axis, from the box edges that do not touch the image's border
// (an edge the border cuts off moved with the border, not with the scene); else the centroids.
double offset(double a0, double a1, double b0, double b1, double ac, double bc, int size) {
  if (a0 > 0 && b0 > 0) return b0 - a0;
  if (a1 < size - 1 && b1 < size - 1) return b1 - a1;
  return bc - ac;
}

Extent extentOf(const CoverageMask& m) {
  Extent e{1e9, 1e9, -1e9, -1e9, 0, 0};
  std::size_t n = 0;
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      if (m.covered[std::size_t(y) * m.width + x]) {
        e.x0 = std::min<double>(e.x0, x), e.x1 = std::max<double>(e.x1, x);
        e.y0 = std::min<double>(e.y0, y), e.y1 = std::max<double>(e.y1, y);
        e.cx += x, e.cy += y, ++n;
      }
  if (n) e.cx /= double(n), e.cy /= double(n);
  return e;
}

CoverageMask flippedVertically(const CoverageMask& m) {
  CoverageMask f = m;
  for (int y = 0; y < m.height; ++y)
    std::copy_n(m.covered.begin() + std::ptrdiff_t(y) * m.width, m.width, f.covered.begin() + std::ptrdiff_t(m.height - 1 - y) * m.width);
  return f;
}

std::string likelyCause(const CoverageMask& tlab, const CoverageMask& theirs, double iou) {
  if (theirs.count() == 0) return "the image shows nothing but background";
  if (intersectionOverUnion(tlab, flippedVertically(theirs)) >= std::max(kMinimumAlignmentIoU, iou + 0.05))
    return "vertical flip (tlab's row 0 is the top of the picture; OpenGL read-backs start at the bottom)";
  const Extent a = extentOf(tlab), b = extentOf(theirs);
  std::ostringstream s;
  s.precision(3);
  const double dx = offset(a.x0, a.x1, b.x0, b.x1, a.cx, b.cx, tlab.width), dy = offset(a.y0, a.y1, b.y0, b.y1, a.cy, b.cy, tlab.height);
  const double movedIou = intersectionOverUnion(translated(tlab, int(std::lround(dx)), int(std::lround(dy))), theirs);
  if (std::hypot(dx, dy) >= 1.0 && movedIou >= std::max(0.9, iou + 0.05)) {
    s << "shifted camera (the scene appears moved by " << dx << ", " << dy << " pixels: eye, target or up differ)";
    return s.str();
  }
  const double sx = b.width() / a.width(), sy = b.height() / a.height();
  if (std::abs(sx - sy) > 0.04 * std::max(sx, sy)) {
    s << "aspect (the scene is scaled " << sx << "x across but " << sy << "x up: the camera's aspect ratio must be the image's W/H)";
    return s.str();
  }
  if (std::abs(sx - 1.0) > 0.03) {
    s << "field of view (the scene appears " << sx << "x as large: tlab's fovy is the vertical angle, in degrees; glTF's yfov in radians)";
    return s.str();
  }
  if (std::hypot(b.cx - a.cx, b.cy - a.cy) > 0.5) {
    s << "shifted camera (the scene's centre appears moved by " << b.cx - a.cx << ", " << b.cy - a.cy << " pixels: eye, target or up differ)";
    return s.str();
  }
  return "a different scene or camera (same size and place, different outline)";
}

}  // namespace

std::size_t CoverageMask::count() const { return std::size_t(std::count(covered.begin(), covered.end(), std::uint8_t(1))); }

CoverageMask imageCoverage(const core::Image& image) {
  CoverageMask m{image.width, image.height, std::vector<std::uint8_t>(image.pixels.size(), 0)};
  if (image.pixels.empty()) return m;
  const bool transparent = std::any_of(image.pixels.begin(), image.pixels.end(), [](const glm::vec4& p) { return p.a < 0.5f; });
  const glm::vec4 background = backgroundOf(image);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    m.covered[i] = transparent ? image.pixels[i].a >= 0.5f : !sameColour(image.pixels[i], background);
  return m;
}

CoverageMask coverageFromCounts(const std::vector<std::uint16_t>& counts, int width, int height) {
  CoverageMask m{width, height, std::vector<std::uint8_t>(counts.size(), 0)};
  for (std::size_t i = 0; i < counts.size(); ++i) m.covered[i] = counts[i] > 0;
  return m;
}

double intersectionOverUnion(const CoverageMask& a, const CoverageMask& b) {
  std::size_t both = 0, either = 0;
  for (std::size_t i = 0; i < a.covered.size() && i < b.covered.size(); ++i) {
    both += a.covered[i] && b.covered[i];
    either += a.covered[i] || b.covered[i];
  }
  return either ? double(both) / double(either) : 1.0;
}

AlignmentResult compareCoverage(const CoverageMask& tlab, const CoverageMask& theirs) {
  AlignmentResult r;
  r.iou = intersectionOverUnion(tlab, theirs);
  r.aligned = r.iou >= kMinimumAlignmentIoU;
  if (!r.aligned) r.likelyCause = likelyCause(tlab, theirs, r.iou);
  return r;
}

core::Image readExternalImage(const std::string& path, int width, int height) {
  auto image = core::readPngFile(path);
  if (!image) throw std::runtime_error(path + ": cannot read the image (a PNG is expected)");
  if (image->width != width || image->height != height)
    throw std::runtime_error(path + ": the image is " + std::to_string(image->width) + "x" + std::to_string(image->height) +
                             " but the stimulus is " + std::to_string(width) + "x" + std::to_string(height));
  return *image;
}

core::Image opaque(core::Image image) {
  for (auto& p : image.pixels) p.a = 1.0f;
  return image;
}

AlignmentResult alignWithView(render::Renderer& renderer, const render::Camera& camera, const core::Image& image) {
  render::RenderRequest request;  // tlab's coverage: the pixels with at least one fragment
  request.width = image.width;
  request.height = image.height;
  request.style = "constant";
  request.camera = camera;
  request.timePasses = false;
  renderer.render(request);
  return compareCoverage(coverageFromCounts(renderer.layerCounts(), image.width, image.height), imageCoverage(image));
}

std::string iouText(double iou) {
  std::ostringstream s;
  s.precision(4);
  s << iou;
  return s.str();
}

std::string misalignmentMessage(const std::string& image, const std::string& what, const AlignmentResult& result) {
  return image + ": IoU " + iouText(result.iou) + " with tlab's coverage of " + what +
         " (below 0.98): the image does not show tlab's view; likely cause: " + result.likelyCause;
}

}  // namespace tlab::stimuli
