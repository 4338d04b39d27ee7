#pragma once
// Procedural scenes by name: `builtin:NAME?param=value&...`. Each scene declares its parameters
// with defaults; unknown names or parameters are errors that list what is known.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "renderer/scene/scene.hpp"

namespace tlab::render {

struct SceneParam {
  std::string name;
  double defaultValue;
  double minValue;
  double maxValue;
  bool integer;
  std::string help;
};

struct BuiltinSceneSpec {
  std::string name;
  std::string help;
  std::vector<SceneParam> params;
  std::function<Scene(const std::map<std::string, double>&)> build;
};

// All built-in scenes, in a stable order. Later libraries (stimuli) add theirs through
// SceneCatalog, so the renderer never depends on them.
const std::vector<BuiltinSceneSpec>& builtinScenes();

// Parses "NAME?a=1&b=2" and builds the scene from `specs`. Throws std::invalid_argument naming
// the bad part.
Scene buildBuiltinScene(const std::string& nameAndQuery, const std::vector<BuiltinSceneSpec>& specs);

// The same checks without building: the scene's spec and its parameter values (defaults filled in).
std::pair<const BuiltinSceneSpec*, std::map<std::string, double>> parseBuiltinScene(const std::string& nameAndQuery,
                                                                                     const std::vector<BuiltinSceneSpec>& specs);

// Mesh primitives used by the scenes (and by later scene generators).
TriangleMesh makeUvSphere(float radius, int segments, int rings);
TriangleMesh makeBox(glm::vec3 halfExtent);
TriangleMesh makeTorus(float majorRadius, float minorRadius, int majorSegments, int minorSegments);
TriangleMesh makeOpenCylinder(float radius, float height, int segments, int rings);
TriangleMesh makeQuad(glm::vec3 center, glm::vec3 axisU, glm::vec3 axisV);
// Two triangles per cell of a (rows+1) x (cols+1) vertex grid laid out row by row, counter-clockwise
// when columns run along u and rows along v (the torus, the cylinder, grid quads).
void appendGridTriangles(TriangleMesh& mesh, int rows, int cols);

}  // namespace tlab::render
