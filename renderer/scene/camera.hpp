#pragma once
// A perspective look-at camera, with its fit to a bounding sphere and orbit.
#include <string>

#include <glm/glm.hpp>

namespace tlab::render {

struct BoundingSphere {
  glm::vec3 center{0.0f};
  float radius = 1.0f;
};

struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 3.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fovyDegrees = 45.0f;
  float nearPlane = 0.1f;
  float farPlane = 100.0f;

  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
};

// A camera looking at the sphere from direction `fromDirection` (world space), at the distance
// where the sphere fills the view (both horizontally and vertically for the given aspect).
Camera fitCamera(const BoundingSphere& sphere, float aspect, float fovyDegrees = 45.0f,
                 glm::vec3 fromDirection = {0.0f, 0.0f, 1.0f});

// Rotates the eye about the target: `azimuthDegrees` about `up`, `elevationDegrees` toward it.
Camera orbit(const Camera& camera, float azimuthDegrees, float elevationDegrees);

// Parses "eye=X,Y,Z target=X,Y,Z up=X,Y,Z fovy=DEG [near=N far=F]" on top of `base`; keys may
// be given in any order and any subset. Throws std::invalid_argument naming the bad field.
Camera parseCamera(const std::string& text, const Camera& base);

// The camera in parseCamera's form, every field given, each number with the shortest text that
// reads back to the same float: parseCamera(cameraText(c), any) == c.
std::string cameraText(const Camera& camera);

}  // namespace tlab::render
