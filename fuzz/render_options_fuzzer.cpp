// Fuzz target: the short texts a researcher gives `tlab render` and the experiment and stimulus
// files beside a scene — the camera ("eye=X,Y,Z target=... up=... fovy=... near=... far=..."),
// a built-in scene's name and query ("torus?triangles=2000"), and the curvature style's inline
// transfer functions ("points:κ=v,..." and "grid:a,b/c,d"). The first byte picks the parser, the
// rest is the text. A rejection is one std::invalid_argument; what is accepted must be usable:
// a camera whose view and projection are finite and whose text (cameraText) reads back as the
// same camera, scene parameters within their declared ranges (whole where they must be), and
// transfer functions with every sample in [0, 1]. (Transfer functions given as PNG files are
// left out: the text would be a path, and reading whatever file it names is not the parser.)
// fuzz-sources: renderer/scene/camera.cpp renderer/scene/builtin_scenes.cpp renderer/params/transfer_function.cpp
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <glm/glm.hpp>

#include "renderer/params/transfer_function.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "renderer/scene/camera.hpp"

namespace {

using namespace tlab::render;

void require(bool ok) {
  if (!ok) std::abort();
}

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

bool same(const Camera& a, const Camera& b) {
  return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fovyDegrees == b.fovyDegrees &&
         a.nearPlane == b.nearPlane && a.farPlane == b.farPlane;
}

void camera(const std::string& text) {
  Camera c;
  try {
    c = parseCamera(text, Camera{});
  } catch (const std::invalid_argument&) {
    return;
  }
  require(finite(c.view()) && finite(c.projection(1.0f)) && finite(c.projection(16.0f / 9.0f)));
  Camera other;
  other.eye = {7.0f, -3.0f, 2.0f};
  other.fovyDegrees = 60.0f;
  require(same(parseCamera(cameraText(c), other), c));
}

void scene(const std::string& text) {
  try {
    const auto [spec, values] = parseBuiltinScene(text, builtinScenes());
    require(values.size() == spec->params.size());
    for (const auto& p : spec->params) {
      const double v = values.at(p.name);
      require(std::isfinite(v) && v >= p.minValue && v <= p.maxValue && (!p.integer || v == std::floor(v)));
    }
  } catch (const std::invalid_argument&) {
  }
}

template <typename Function, typename Check>
void transferFunction(const std::string& text, const char* prefix, Check check) {
  if (text.rfind(prefix, 0) != 0) return;  // not inline: a PNG path
  try {
    const Function f = Function::parse(text);
    for (const auto& s : f.samples()) check(s);
  } catch (const std::invalid_argument&) {
  }
}

bool unit(float v) { return v >= 0.0f && v <= 1.0f; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  switch (data[0] % 4) {
    case 0: camera(text); break;
    case 1: scene(text); break;
    case 2:
      transferFunction<CurvatureShadingFunction>(text, "points:", [](const glm::vec3& s) { require(unit(s.r) && unit(s.g) && unit(s.b)); });
      break;
    default: transferFunction<CurvatureOpacityFunction>(text, "grid:", [](float s) { require(unit(s)); }); break;
  }
  return 0;
}
