#pragma once
// The camera of a stimulus image as geometry: the eye ray through a pixel position and the pixel
// position of a world point, in double precision. Image convention: pixel (x, y) covers
// [x, x+1) × [y, y+1) with row 0 = top; the ray of pixel (x, y) goes through (x + 0.5, y + 0.5).
#include <glm/glm.hpp>

#include "renderer/scene/camera.hpp"

namespace tlab::tasks {

struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};  // unit length
};

class ViewGeometry {
 public:
  ViewGeometry(const render::Camera& camera, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  glm::dvec3 eye() const { return eye_; }
  glm::dvec3 forward() const { return forward_; }
  // The image's right in world coordinates (unit; perpendicular to forward()).
  glm::dvec3 right() const { return right_; }

  // The eye ray through a continuous pixel position (use (x + 0.5, y + 0.5) for pixel centres).
  Ray rayThrough(glm::dvec2 pixelPosition) const;
  Ray rayThroughPixelCenter(glm::ivec2 pixel) const { return rayThrough(glm::dvec2(pixel) + 0.5); }
  // The continuous pixel position of a world point (in front of the eye).
  glm::dvec2 project(glm::dvec3 world) const;
  // Distance of a point in front of the eye along the viewing direction.
  double depth(glm::dvec3 world) const { return glm::dot(world - eye_, forward_); }
  // True when the point is in front of the eye and at least `marginPixels` inside the image.
  bool inImage(glm::dvec3 world, double marginPixels) const;
  // World length of one pixel at a view depth (vertical field of view / height).
  double pixelFootprint(double depth) const;

 private:
  int width_, height_;
  glm::dvec3 eye_, forward_, right_;
  glm::dmat4 viewProjection_, inverseViewProjection_;
  double tanHalfFovy_;
};

}  // namespace tlab::tasks
