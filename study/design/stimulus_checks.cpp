// The renderer's checks of every stimulus of an experiment file (stimulus_checks.hpp).
#include "study/design/stimulus_checks.hpp"

#include <map>

#include "renderer/scene/scene_source.hpp"
#include "renderer/styles/style.hpp"
#include "study/design/scene_catalog.hpp"

namespace tlab::study {

namespace {

// Where one part of a stimulus was set: the field's name and node, for file:line messages.
struct StimulusSource {
  const toml::node* node = nullptr;
  std::string field;
};

struct StimulusParts {
  std::string scene, style;
  std::vector<std::string> settings;
  StimulusSource sceneFrom, styleFrom;
  std::vector<std::pair<std::string, StimulusSource>> settingsFrom;  // each setting and where it was set
};

const toml::node* nodeAt(const toml::table& root, const std::vector<std::string>& path, const std::vector<std::size_t>& index) {
  const toml::node* n = &root;
  for (std::size_t i = 0; i < path.size() && n; ++i) {
    n = n->as_table() ? n->as_table()->get(path[i]) : nullptr;
    if (n && i < index.size() && index[i] > 0) n = n->as_array() ? n->as_array()->get(index[i] - 1) : nullptr;
  }
  return n;
}

// The node of `key` inside a table node (the table itself when the key is absent).
const toml::node* keyNode(const toml::node* table, const char* key) {
  const toml::node* n = table && table->as_table() ? table->as_table()->get(key) : nullptr;
  return n ? n : table;
}

void applyLevel(StimulusParts& p, const toml::table& root, const Level& level, std::size_t f, std::size_t l) {
  const std::string where = "factors[" + std::to_string(f + 1) + "].levels[" + std::to_string(l + 1) + "]";
  const toml::node* node = nodeAt(root, {"factors", "levels"}, {f + 1, l + 1});
  if (level.scene) p.scene = *level.scene, p.sceneFrom = {keyNode(node, "scene"), where + ".scene"};
  if (level.style) p.style = *level.style, p.styleFrom = {keyNode(node, "style"), where + ".style"};
  for (const auto& s : level.renderSettings) p.settingsFrom.push_back({s, {keyNode(node, "settings"), where + ".settings"}});
}

// The renderer's own checks of one stimulus (scene source, style, settings), with the field that set the failing part.
void checkStimulus(const FieldReader& r, const StimulusParts& p) {
  std::string scene = p.scene;  // checked as the first trial's instance
  for (auto at = scene.find("{trial}"); at != std::string::npos; at = scene.find("{trial}")) scene.replace(at, 7, "1");
  try {
    render::checkSceneSource(scene, sceneCatalog());
  } catch (const std::exception& e) {
    r.fail(p.sceneFrom.node, p.sceneFrom.field, e.what());
  }
  try {
    std::map<std::string, std::string> settings;
    for (const auto& [s, from] : p.settingsFrom) render::addSetting(settings, s);
    render::findStyle(p.style).resolve(settings);
  } catch (const std::exception& e) {
    const std::string message = e.what();
    StimulusSource blamed = p.styleFrom;
    for (const auto& [s, from] : p.settingsFrom)
      if (message.find("'" + s.substr(0, s.find('=')) + "'") != std::string::npos || s.find('=') == std::string::npos) blamed = from;
    r.fail(blamed.node, blamed.field, message);
  }
}

}  // namespace

void checkStimuli(const FieldReader& r, const toml::table& root, const Experiment& e) {
  StimulusParts base;
  base.scene = e.stimulus.scene;
  base.style = e.stimulus.style;
  const toml::node* stimulus = root.get("stimulus") ? root.get("stimulus") : &root;
  base.sceneFrom = {keyNode(stimulus, "scene"), "stimulus.scene"};
  base.styleFrom = {keyNode(stimulus, "style"), "stimulus.style"};
  for (const auto& s : e.stimulus.renderSettings) base.settingsFrom.push_back({s, {keyNode(stimulus, "settings"), "stimulus.settings"}});
  std::vector<std::size_t> level(e.factors.size(), 0);
  for (int combinations = 0; combinations < 4096; ++combinations) {
    StimulusParts parts = base;
    for (std::size_t f = 0; f < e.factors.size(); ++f) applyLevel(parts, root, e.factors[f].levels[level[f]], f, level[f]);
    checkStimulus(r, parts);
    for (std::size_t t = 0; t < e.tasks.size(); ++t)
      if (e.tasks[t].scene) {
        StimulusParts withTask = parts;
        withTask.scene = *e.tasks[t].scene;
        withTask.sceneFrom = {keyNode(nodeAt(root, {"tasks"}, {t + 1}), "scene"), "tasks[" + std::to_string(t + 1) + "].scene"};
        checkStimulus(r, withTask);
      }
    std::size_t f = 0;  // the next combination, like an odometer
    while (f < level.size() && ++level[f] == e.factors[f].levels.size()) level[f++] = 0;
    if (f == level.size()) return;
  }
}

}  // namespace tlab::study
