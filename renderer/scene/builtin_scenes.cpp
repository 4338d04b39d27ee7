#include "renderer/scene/builtin_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/seeded_random.hpp"
#include "core/parse_number.hpp"

namespace tlab::render {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// A qualitative palette for objects (front colours); back colours are a cooler variant.
glm::vec4 paletteColor(std::size_t i) {
  static const glm::vec4 colors[] = {
      {0.90f, 0.55f, 0.20f, 1}, {0.25f, 0.55f, 0.85f, 1}, {0.35f, 0.70f, 0.35f, 1},
      {0.80f, 0.30f, 0.35f, 1}, {0.60f, 0.45f, 0.75f, 1}, {0.85f, 0.75f, 0.25f, 1},
      {0.30f, 0.70f, 0.70f, 1}, {0.65f, 0.50f, 0.35f, 1}};
  return colors[i % std::size(colors)];
}

SceneObject makeObject(std::string name, TriangleMesh mesh, std::size_t colorIndex) {
  SceneObject o;
  o.name = std::move(name);
  o.mesh = std::move(mesh);
  o.frontColor = paletteColor(colorIndex);
  o.backColor = glm::vec4(glm::vec3(o.frontColor) * 0.55f + glm::vec3(0.1f, 0.15f, 0.3f), 1.0f);
  return o;
}

int asInt(const std::map<std::string, double>& p, const char* key) {
  return static_cast<int>(std::lround(p.at(key)));
}
float asFloat(const std::map<std::string, double>& p, const char* key) {
  return static_cast<float>(p.at(key));
}

Scene sphereScene(const std::map<std::string, double>& p) {
  Scene s;
  s.name = "sphere";
  s.objects.push_back(makeObject("sphere", makeUvSphere(asFloat(p, "radius"), asInt(p, "segments"), asInt(p, "rings")), 0));
  return s;
}

// n closed concentric spheres of radii k/n (k = 1..n): 2n layers through the centre.
Scene nestedSpheresScene(const std::map<std::string, double>& p) {
  Scene s;
  s.name = "nested-spheres";
  const int n = asInt(p, "n");
  for (int k = n; k >= 1; --k)
    s.objects.push_back(makeObject("shell-" + std::to_string(k),
                                   makeUvSphere(float(k) / float(n), asInt(p, "segments"), asInt(p, "rings")),
                                   std::size_t(n - k)));
  return s;
}

Scene cubeScene(const std::map<std::string, double>& p) {
  Scene s;
  s.name = "cube";
  const float h = 0.5f * asFloat(p, "size");
  s.objects.push_back(makeObject("cube", makeBox(glm::vec3(h)), 0));
  // A generic view: three faces visible, as in Carnecky Fig. 11.
  s.camera = Camera{};
  s.camera->eye = glm::vec3(2.2f, 1.7f, 2.6f) * h * 2.0f;
  s.camera->target = glm::vec3(0.0f);
  s.camera->nearPlane = 0.1f * h;
  s.camera->farPlane = 20.0f * h;
  return s;
}

Scene torusScene(const std::map<std::string, double>& p) {
  Scene s;
  s.name = "torus";
  int major = asInt(p, "major_segments"), minor = asInt(p, "minor_segments");
  const int triangles = asInt(p, "triangles");
  if (triangles > 0) {
    // 2 * major * minor triangles with major = 2 * minor.
    minor = std::max(3, static_cast<int>(std::lround(std::sqrt(triangles / 4.0))));
    major = 2 * minor;
  }
  s.objects.push_back(makeObject("torus", makeTorus(asFloat(p, "major_radius"), asFloat(p, "minor_radius"), major, minor), 0));
  // Tilted so that the hole and both sides show.
  s.camera = Camera{};
  s.camera->eye = glm::vec3(0.0f, 2.2f, 2.4f);
  s.camera->target = glm::vec3(0.0f);
  s.camera->nearPlane = 0.5f;
  s.camera->farPlane = 8.0f;
  return s;
}

// Two open concentric cylinders (Carnecky Fig. 2): silhouettes and rims.
Scene openCylindersScene(const std::map<std::string, double>& p) {
  Scene s;
  s.name = "open-cylinders";
  const int seg = asInt(p, "segments"), rings = asInt(p, "rings");
  s.objects.push_back(makeObject("outer", makeOpenCylinder(1.0f, 2.0f, seg, rings), 0));
  s.objects.push_back(makeObject("inner", makeOpenCylinder(0.55f, 2.8f, seg, rings), 1));
  s.camera = Camera{};
  s.camera->eye = glm::vec3(0.0f, 2.0f, 4.6f);
  s.camera->target = glm::vec3(0.0f, 0.1f, 0.0f);
  s.camera->nearPlane = 1.0f;
  s.camera->farPlane = 12.0f;
  return s;
}

// n parallel full-screen quads at random depths, object ids cycling through m (Murray Sec. 6).
Scene quadStackScene(const std::map<std::string, double>& p) {
  Scene s;
  s.name = "quad-stack";
  const int n = asInt(p, "n"), m = asInt(p, "m");
  core::SeededRandom rng(static_cast<std::uint64_t>(p.at("seed")));
  std::set<float> used;
  for (int i = 0; i < n; ++i) {
    float z;
    do z = rng.uniform(-1.0f, 1.0f);
    while (!used.insert(z).second);
    const int object = i % m;
    if (static_cast<int>(s.objects.size()) <= object)
      s.objects.push_back(makeObject("quads-" + std::to_string(object), TriangleMesh{}, std::size_t(object)));
    appendMesh(s.objects[object].mesh, makeQuad({0, 0, z}, {20, 0, 0}, {0, 20, 0}));
  }
  s.camera = Camera{};
  s.camera->eye = glm::vec3(0.0f, 0.0f, 5.0f);
  s.camera->target = glm::vec3(0.0f);
  s.camera->nearPlane = 1.0f;
  s.camera->farPlane = 10.0f;
  return s;
}

std::string knownNames(const std::vector<BuiltinSceneSpec>& specs) {
  std::string out;
  for (const auto& s : specs) out += (out.empty() ? "" : ", ") + s.name;
  return out;
}

}  // namespace

void appendGridTriangles(TriangleMesh& m, int rows, int cols) {
  const auto idx = [&](int r, int c) { return static_cast<std::uint32_t>(r * (cols + 1) + c); };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      m.triangles.push_back({idx(r, c), idx(r, c + 1), idx(r + 1, c)});
      m.triangles.push_back({idx(r, c + 1), idx(r + 1, c + 1), idx(r + 1, c)});
    }
}

TriangleMesh makeUvSphere(float radius, int segments, int rings) {
  TriangleMesh m;
  for (int r = 0; r <= rings; ++r) {
    const float v = float(r) / float(rings), theta = v * kPi;
    for (int s = 0; s <= segments; ++s) {
      const float u = float(s) / float(segments), phi = u * 2.0f * kPi;
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      m.positions.push_back(radius * n);
      m.normals.push_back(n);
      m.st.push_back({u, v});
    }
  }
  const auto idx = [&](int r, int s) { return static_cast<std::uint32_t>(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      // Outward-facing counter-clockwise winding; skip the degenerate triangles at the poles.
      if (r != 0) m.triangles.push_back({idx(r, s), idx(r, s + 1), idx(r + 1, s)});
      if (r != rings - 1) m.triangles.push_back({idx(r, s + 1), idx(r + 1, s + 1), idx(r + 1, s)});
    }
  return m;
}

TriangleMesh makeQuad(glm::vec3 center, glm::vec3 axisU, glm::vec3 axisV) {
  TriangleMesh m;
  const glm::vec3 n = glm::normalize(glm::cross(axisU, axisV));
  const glm::vec2 st[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const auto& c : st) {
    m.positions.push_back(center + (2.0f * c.x - 1.0f) * axisU + (2.0f * c.y - 1.0f) * axisV);
    m.normals.push_back(n);
    m.st.push_back(c);
  }
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

TriangleMesh makeBox(glm::vec3 h) {
  TriangleMesh m;
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int a = 0; a < 3; ++a)
    for (float sign : {1.0f, -1.0f}) {
      const glm::vec3 n = sign * axes[a];
      const glm::vec3 u = axes[(a + 1) % 3] * h[(a + 1) % 3] * sign;
      const glm::vec3 v = axes[(a + 2) % 3] * h[(a + 2) % 3];
      appendMesh(m, makeQuad(n * h[a], u, v));
    }
  return m;
}

TriangleMesh makeTorus(float R, float r, int majorSegments, int minorSegments) {
  TriangleMesh m;
  for (int i = 0; i <= majorSegments; ++i) {
    const float u = float(i) / float(majorSegments), phi = u * 2.0f * kPi;
    for (int j = 0; j <= minorSegments; ++j) {
      const float v = float(j) / float(minorSegments), theta = v * 2.0f * kPi;
      const glm::vec3 n(std::cos(theta) * std::cos(phi), std::sin(theta), std::cos(theta) * std::sin(phi));
      const glm::vec3 c(R * std::cos(phi), 0.0f, R * std::sin(phi));
      m.positions.push_back(c + r * n);
      m.normals.push_back(n);
      m.st.push_back({u, v});
    }
  }
  appendGridTriangles(m, majorSegments, minorSegments);
  return m;
}

TriangleMesh makeOpenCylinder(float radius, float height, int segments, int rings) {
  TriangleMesh m;
  for (int r = 0; r <= rings; ++r) {
    const float t = float(r) / float(rings);
    for (int s = 0; s <= segments; ++s) {
      const float u = float(s) / float(segments), phi = u * 2.0f * kPi;
      const glm::vec3 n(std::cos(phi), 0.0f, -std::sin(phi));
      m.positions.push_back({radius * n.x, (t - 0.5f) * height, radius * n.z});
      m.normals.push_back(n);
      m.st.push_back({u, t});
    }
  }
  appendGridTriangles(m, rings, segments);
  return m;
}

const std::vector<BuiltinSceneSpec>& builtinScenes() {
  static const std::vector<BuiltinSceneSpec> specs = {
      {"sphere", "a unit sphere", {{"radius", 1, 1e-3, 1e3, false, "radius"}, {"segments", 64, 3, 4096, true, "longitude segments"}, {"rings", 32, 2, 4096, true, "latitude rings"}}, sphereScene},
      {"nested-spheres", "n closed concentric spheres of radii k/n", {{"n", 3, 1, 64, true, "number of shells"}, {"segments", 64, 3, 4096, true, "longitude segments"}, {"rings", 32, 2, 4096, true, "latitude rings"}}, nestedSpheresScene},
      {"cube", "an axis-aligned cube seen from a generic view", {{"size", 1, 1e-3, 1e3, false, "edge length"}}, cubeScene},
      {"torus", "a torus (Carnecky Figs. 14-15 timing scene)", {{"major_radius", 1, 1e-3, 1e3, false, "ring radius"}, {"minor_radius", 0.4, 1e-3, 1e3, false, "tube radius"}, {"major_segments", 128, 3, 100000, true, "segments around the ring"}, {"minor_segments", 64, 3, 100000, true, "segments around the tube"}, {"triangles", 0, 0, 1e8, true, "approximate triangle count (overrides the segments when > 0)"}}, torusScene},
      {"open-cylinders", "two open concentric cylinders (Carnecky Fig. 2)", {{"segments", 96, 3, 100000, true, "segments around"}, {"rings", 8, 1, 100000, true, "segments along the axis"}}, openCylindersScene},
      {"quad-stack", "n parallel full-screen quads at random depths with m object ids (Murray Sec. 6)", {{"n", 32, 1, 4096, true, "number of quads"}, {"m", 1, 1, 4096, true, "number of object ids"}, {"seed", 1, 0, 4294967295.0, true, "random seed for the depths"}}, quadStackScene},
  };
  return specs;
}

Scene buildBuiltinScene(const std::string& nameAndQuery, const std::vector<BuiltinSceneSpec>& specs) {
  const auto [spec, values] = parseBuiltinScene(nameAndQuery, specs);
  return spec->build(values);
}

std::pair<const BuiltinSceneSpec*, std::map<std::string, double>> parseBuiltinScene(const std::string& nameAndQuery,
                                                                                     const std::vector<BuiltinSceneSpec>& specs) {
  const auto q = nameAndQuery.find('?');
  const std::string name = nameAndQuery.substr(0, q);
  const auto spec = std::find_if(specs.begin(), specs.end(), [&](const auto& s) { return s.name == name; });
  if (spec == specs.end())
    throw std::invalid_argument("unknown built-in scene '" + name + "' (known: " + knownNames(specs) + ")");
  std::map<std::string, double> values;
  for (const auto& p : spec->params) values[p.name] = p.defaultValue;
  if (q != std::string::npos) {
    std::istringstream in(nameAndQuery.substr(q + 1));
    std::string pair;
    while (std::getline(in, pair, '&')) {
      if (pair.empty()) continue;
      const auto eq = pair.find('=');
      const std::string key = pair.substr(0, eq);
      const auto param = std::find_if(spec->params.begin(), spec->params.end(), [&](const auto& p) { return p.name == key; });
      if (param == spec->params.end()) {
        std::string known;
        for (const auto& p : spec->params) known += (known.empty() ? "" : ", ") + p.name;
        throw std::invalid_argument("built-in scene '" + name + "' has no parameter '" + key + "' (known: " + known + ")");
      }
      const std::string text = eq == std::string::npos ? "" : pair.substr(eq + 1);
      const auto parsed = core::parseFiniteNumber(text);
      if (!parsed)
        throw std::invalid_argument("built-in scene '" + name + "' parameter '" + key + "': '" + text + "' is not a number");
      const double v = *parsed;
      if (param->integer && v != std::floor(v))
        throw std::invalid_argument("built-in scene '" + name + "' parameter '" + key + "' must be a whole number, got " + text);
      if (v < param->minValue || v > param->maxValue) {
        throw std::invalid_argument("built-in scene '" + name + "' parameter '" + key + "' = " + text + " is outside [" +
                                    core::roundTripText(param->minValue) + ", " + core::roundTripText(param->maxValue) + "]");
      }
      values[key] = v;
    }
  }
  return {&*spec, values};
}

}  // namespace tlab::render
