#pragma once
// What the IRIS style GL tests share (iris_styles_gl_test.cpp: closed forms; iris_effects_gl_test.cpp:
// the effects one by one): the α probe sphere, the front camera, the stretched (s, t) quad and the
// settings that make a quad's image the stripe pattern itself.
#include <map>
#include <string>

#include "renderer/pipeline/renderer.hpp"
#include "renderer/scene/builtin_scenes.hpp"

namespace tlab::testing {

using namespace tlab::render;

// A unit sphere, white in front and black behind, on black: the image is the front layer's α.
inline Scene alphaProbeSphere() {
  Scene s;
  SceneObject o;
  o.name = "sphere";
  o.mesh = makeUvSphere(1.0f, 192, 96);
  o.frontColor = {1, 1, 1, 1};
  o.backColor = {0, 0, 0, 1};
  s.objects.push_back(o);
  s.background = {0, 0, 0, 1};
  return s;
}

inline Camera frontCamera() {
  Camera c;
  c.eye = {0, 0, 3};
  c.target = {0, 0, 0};
  c.fovyDegrees = 45.0f;
  c.nearPlane = 1.0f;
  c.farPlane = 5.0f;
  return c;
}

// A white quad on black whose image is the stripe pattern itself (α = c(s, t) of Eq. 5).
inline std::map<std::string, std::string> patternSettings(const std::string& axis, double period) {
  return {{"opacity", "constant"}, {"alpha", "1"},           {"stripes", axis},      {"stripe_period", std::to_string(period)},
          {"stripe_strength", "1"}, {"stripe_darken", "0"}, {"lighting", "none"},  {"specular", "0"}};
}

inline Scene stretchedQuad(glm::vec2 stScale) {
  Scene s;
  SceneObject o;
  o.mesh = makeQuad({0, 0, 0}, {2, 0, 0}, {0, 2, 0});
  for (auto& st : o.mesh.st) st *= stScale;
  o.frontColor = o.backColor = {1, 1, 1, 1};
  s.objects.push_back(o);
  s.background = {0, 0, 0, 1};
  return s;
}

// `scene` in `style` at size × size from the front camera, unlit, showing only the effect the
// settings ask for: `iris` defaults to the IRIS look (stripes, silhouettes), off unless set.
inline tlab::core::Image renderOneEffect(const Scene& scene, const std::string& style, int size,
                                         std::map<std::string, std::string> settings) {
  Renderer renderer(scene);
  RenderRequest r;
  r.width = r.height = size;
  r.style = style;
  r.camera = frontCamera();
  settings["lighting"] = "none";
  settings["specular"] = "0";
  settings.emplace("stripes", "off");
  settings.emplace("silhouettes", "off");
  r.settings = settings;
  return renderer.render(r);
}

}  // namespace tlab::testing
