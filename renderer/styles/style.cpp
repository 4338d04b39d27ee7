#include "renderer/styles/style.hpp"

#include <mutex>
#include <stdexcept>

#include "renderer/styles/constant_style.hpp"
#include "renderer/styles/dynamic_style.hpp"
#include "renderer/styles/file_style.hpp"
#include "renderer/styles/curvature_style.hpp"
#include "renderer/styles/iris_style.hpp"
#include "renderer/styles/opaque_style.hpp"
#include "renderer/styles/smart_style.hpp"
#include "renderer/styles/unsorted_style.hpp"
#include "renderer/styles/view_dependent_style.hpp"

namespace tlab::render {

ParamSpec lightingParam(const std::string& defaultValue) {
  return ParamSpec::choice("lighting", defaultValue, {"headlight", "pbr", "none"},
                           "surface shading before transparency: two-sided headlight diffuse, physically based "
                           "(Disney diffuse + GGX, key light and procedural sky, seed 002 Sec. 4.2), or the flat colour");
}

int lightingModel(const StyleParams& params) {
  if (params.is("lighting", "none")) return 0;
  return params.is("lighting", "pbr") ? 2 : 1;
}

std::vector<ParamSpec> Style::allParams() const {
  auto specs = params();
  for (const auto& s : specs)
    if (s.name == "lighting") return specs;  // the style chose its own default
  specs.push_back(lightingParam("headlight"));
  return specs;
}

StyleParams Style::resolve(const std::map<std::string, std::string>& settings) const {
  StyleParams resolved(name(), allParams(), settings);
  validate(resolved);
  return resolved;
}

namespace {
const std::vector<std::unique_ptr<Style>>& registry() {
  static const auto styles = [] {
    std::vector<std::unique_ptr<Style>> s;
    s.push_back(std::make_unique<OpaqueStyle>());
    s.push_back(std::make_unique<ConstantStyle>());
    s.push_back(std::make_unique<UnsortedStyle>());
    s.push_back(std::make_unique<SmartStyle>());
    s.push_back(std::make_unique<IrisStyle>("angle", IllustrativeSettings::Opacity::Angle, false));
    s.push_back(std::make_unique<IrisStyle>("normal-variation", IllustrativeSettings::Opacity::NormalVariation, false));
    s.push_back(std::make_unique<IrisStyle>("iris", IllustrativeSettings::Opacity::Constant, true));
    s.push_back(std::make_unique<ViewDependentStyle>());
    s.push_back(std::make_unique<DynamicStyle>());
    s.push_back(std::make_unique<CurvatureStyle>());
    return s;
  }();
  return styles;
}
// Style files loaded so far, by path and content: a reference handed out stays valid for the
// process even when the file is edited (the edited text is another entry).
const Style& loadedStyleFile(const std::string& path) {
  static std::mutex mutex;
  static std::map<std::pair<std::string, std::string>, std::unique_ptr<FileStyle>> loaded;
  StyleFile file = loadStyleFile(path);
  const std::lock_guard<std::mutex> lock(mutex);
  auto& slot = loaded[{path, file.sha256}];
  if (!slot) slot = std::make_unique<FileStyle>(std::move(file));
  return *slot;
}

}  // namespace

std::vector<std::string> styleNames() {
  std::vector<std::string> names;
  for (const auto& s : registry()) names.push_back(s->name());
  return names;
}

const Style& findStyle(const std::string& name) {
  if (isStyleFilePath(name)) return loadedStyleFile(name);
  for (const auto& s : registry())
    if (s->name() == name) return *s;
  std::string known;
  for (const auto& n : styleNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown style '" + name + "' (known: " + known + ")");
}

}  // namespace tlab::render
