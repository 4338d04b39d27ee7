#include "renderer/scene/camera.hpp"

#include <charconv>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "core/parse_number.hpp"

namespace tlab::render {

glm::mat4 Camera::view() const { return glm::lookAt(eye, target, up); }

glm::mat4 Camera::projection(float aspect) const {
  return glm::perspective(glm::radians(fovyDegrees), aspect, nearPlane, farPlane);
}

Camera fitCamera(const BoundingSphere& sphere, float aspect, float fovyDegrees, glm::vec3 fromDirection) {
  Camera c;
  c.fovyDegrees = fovyDegrees;
  const float halfY = glm::radians(fovyDegrees) * 0.5f;
  const float halfX = std::atan(std::tan(halfY) * aspect);
  const float half = std::min(halfX, halfY);
  const float distance = 1.05f * sphere.radius / std::sin(half);  // a 5 % margin
  const glm::vec3 dir = glm::normalize(fromDirection);
  c.target = sphere.center;
  c.eye = sphere.center + dir * distance;
  c.up = std::abs(glm::dot(dir, glm::vec3(0, 1, 0))) > 0.99f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
  c.nearPlane = std::max(distance - sphere.radius * 1.05f, distance * 1e-3f);
  c.farPlane = distance + sphere.radius * 1.05f;
  return c;
}

Camera orbit(const Camera& camera, float azimuthDegrees, float elevationDegrees) {
  Camera c = camera;
  const glm::vec3 offset = camera.eye - camera.target;
  const glm::vec3 up = glm::normalize(camera.up);
  glm::mat4 r = glm::rotate(glm::mat4(1.0f), glm::radians(azimuthDegrees), up);
  glm::vec3 rotated = glm::vec3(r * glm::vec4(offset, 0.0f));
  const glm::vec3 right = glm::normalize(glm::cross(up, rotated));
  r = glm::rotate(glm::mat4(1.0f), glm::radians(-elevationDegrees), right);
  rotated = glm::vec3(r * glm::vec4(rotated, 0.0f));
  c.eye = camera.target + rotated;
  return c;
}

namespace {

float parseFloat(const std::string& s, const std::string& field) {
  const auto v = core::parseFiniteNumber(s);
  if (!v) throw std::invalid_argument("--camera field '" + field + "': '" + s + "' is not a number");
  if (std::abs(*v) > double(std::numeric_limits<float>::max()))
    throw std::invalid_argument("--camera field '" + field + "': '" + s + "' is beyond a float's range");
  return static_cast<float>(*v);
}

bool finite(const glm::mat4& m) {
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row)
      if (!std::isfinite(m[column][row])) return false;
  return true;
}

glm::vec3 parseVec3(const std::string& s, const std::string& field) {
  std::istringstream in(s);
  std::string part;
  float v[3];
  int n = 0;
  while (std::getline(in, part, ',')) {
    if (n == 3) break;
    v[n++] = parseFloat(part, field);
  }
  if (n != 3 || std::count(s.begin(), s.end(), ',') != 2)
    throw std::invalid_argument("--camera field '" + field + "': expected X,Y,Z, got '" + s + "'");
  return {v[0], v[1], v[2]};
}

// Throws where no view or projection can be built from c: eye and target apart (by a finite
// distance), an up vector that is not zero and not along the line of sight, a look-at matrix a
// float can hold, a field of view in (0, 180) degrees and 0 < near < far.
void checkViewable(const Camera& c) {
  const glm::vec3 sight = c.target - c.eye;
  const float distance = glm::length(sight);
  if (c.eye == c.target) throw std::invalid_argument("--camera: eye equals target");
  if (!(distance > 0.0f)) throw std::invalid_argument("--camera: eye and target are too close together for a float");
  if (!std::isfinite(distance)) throw std::invalid_argument("--camera: eye and target are too far apart");
  const float upLength = glm::length(c.up);
  if (!(upLength > 0.0f)) throw std::invalid_argument("--camera field 'up': must not be zero");
  if (!std::isfinite(upLength)) throw std::invalid_argument("--camera field 'up': too long for a float (give a direction)");
  if (!(glm::length(glm::cross(sight / distance, c.up / upLength)) > 1e-4f))
    throw std::invalid_argument("--camera field 'up': points along the line of sight from eye to target; give one across it");
  const glm::mat4 view = c.view();
  const float turn = glm::determinant(glm::mat3(view));  // 1 for a proper look-at
  if (!(std::abs(turn - 1.0f) < 1e-3f && finite(view)))
    throw std::invalid_argument("--camera: no view a float can hold from this eye, target and up (give up as a direction about 1 long)");
  if (!(c.fovyDegrees > 0.0f && c.fovyDegrees < 180.0f))
    throw std::invalid_argument("--camera field 'fovy': must be in (0, 180) degrees");
  if (!(c.nearPlane > 0.0f && c.farPlane > c.nearPlane))
    throw std::invalid_argument("--camera: need 0 < near < far");
  if (!finite(c.projection(1.0f)))
    throw std::invalid_argument("--camera: near and far give no projection (they lie too far apart for a float)");
}

}  // namespace

Camera parseCamera(const std::string& text, const Camera& base) {
  Camera c = base;
  std::istringstream in(text);
  std::string token;
  while (in >> token) {
    const auto eq = token.find('=');
    if (eq == std::string::npos)
      throw std::invalid_argument("--camera: expected key=value, got '" + token + "'");
    const std::string key = token.substr(0, eq), value = token.substr(eq + 1);
    if (key == "eye") c.eye = parseVec3(value, key);
    else if (key == "target") c.target = parseVec3(value, key);
    else if (key == "up") c.up = parseVec3(value, key);
    else if (key == "fovy") c.fovyDegrees = parseFloat(value, key);
    else if (key == "near") c.nearPlane = parseFloat(value, key);
    else if (key == "far") c.farPlane = parseFloat(value, key);
    else
      throw std::invalid_argument("--camera: unknown field '" + key + "' (known: eye, target, up, fovy, near, far)");
  }
  checkViewable(c);
  return c;
}

namespace {

std::string shortest(float v) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
  return std::string(buffer, end);
}

std::string vec3Text(const glm::vec3& v) { return shortest(v.x) + "," + shortest(v.y) + "," + shortest(v.z); }

}  // namespace

std::string cameraText(const Camera& c) {
  return "eye=" + vec3Text(c.eye) + " target=" + vec3Text(c.target) + " up=" + vec3Text(c.up) + " fovy=" + shortest(c.fovyDegrees) +
         " near=" + shortest(c.nearPlane) + " far=" + shortest(c.farPlane);
}

}  // namespace tlab::render
