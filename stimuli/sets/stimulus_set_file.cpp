#include "stimuli/sets/stimulus_set_file.hpp"
#include "core/file_text.hpp"
#include "core/toml_syntax_message.hpp"

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include <toml++/toml.h>

#include "renderer/styles/style.hpp"
#include "renderer/styles/style_file.hpp"

namespace tlab::stimuli {

namespace {

// Reads one table, tracking the file and the field path for error messages.
class TableReader {
 public:
  TableReader(const toml::table& table, std::string file, std::string path) : table_(table), file_(std::move(file)), path_(std::move(path)) {}

  [[noreturn]] void fail(const toml::node* node, const std::string& key, const std::string& message) const {
    const int line = node ? int(node->source().begin.line) : int(table_.source().begin.line);
    throw StimulusSetError(file_ + ":" + std::to_string(line) + ": " + field(key) + ": " + message);
  }

  std::string field(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  SourcePlace place(const std::string& key) const {
    const toml::node* n = table_.get(key);
    return {file_, int((n ? n->source() : table_.source()).begin.line), field(key)};
  }

  // Every key must be one of `known`.
  void allowOnly(const std::set<std::string>& known) const {
    for (const auto& [key, node] : table_) {
      if (known.count(std::string(key.str()))) continue;
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      fail(&node, std::string(key.str()), "unknown key (known: " + list + ")");
    }
  }

  std::optional<std::string> text(const std::string& key) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    if (!n->is_string()) fail(n, key, "expected a string");
    return std::string(n->as_string()->get());
  }
  std::optional<double> number(const std::string& key) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    if (n->is_integer()) return double(n->as_integer()->get());
    if (n->is_floating_point()) return n->as_floating_point()->get();
    fail(n, key, "expected a number");
  }
  std::optional<std::int64_t> integer(const std::string& key, std::int64_t lo, std::int64_t hi) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    if (!n->is_integer()) fail(n, key, "expected a whole number");
    const std::int64_t v = n->as_integer()->get();
    if (v < lo || v > hi) fail(n, key, std::to_string(v) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
  }
  std::optional<bool> boolean(const std::string& key) const {
    const toml::node* n = table_.get(key);
    if (!n) return std::nullopt;
    if (!n->is_boolean()) fail(n, key, "expected true or false");
    return n->as_boolean()->get();
  }
  std::vector<std::string> strings(const std::string& key) const {
    std::vector<std::string> out;
    const toml::node* n = table_.get(key);
    if (!n) return out;
    if (!n->is_array()) fail(n, key, "expected an array of strings");
    for (const auto& item : *n->as_array()) {
      if (!item.is_string()) fail(&item, key, "expected an array of strings");
      out.emplace_back(item.as_string()->get());
    }
    return out;
  }
  const toml::array* array(const std::string& key) const {
    const toml::node* n = table_.get(key);
    if (!n) return nullptr;
    if (!n->is_array()) fail(n, key, "expected an array");
    return n->as_array();
  }
  const toml::table& table() const { return table_; }
  const std::string& file() const { return file_; }

 private:
  const toml::table& table_;
  std::string file_, path_;
};

std::map<std::string, std::string> parseSettings(const TableReader& r, const std::string& key, const toml::node* where) {
  std::map<std::string, std::string> out;
  for (const auto& s : r.strings(key)) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0) r.fail(where, key, "expected key=value, got '" + s + "'");
    out[s.substr(0, eq)] = s.substr(eq + 1);
  }
  return out;
}

// { name = "theirs", images = "renders/{scene}-{view}.png" }: a PNG path template whose
// placeholders are {scene} and {view} only.
void readImages(const TableReader& r, const toml::node& node, StyleEntry& style) {
  const auto images = r.text("images");
  if (!images) return;
  const toml::node* where = node.as_table()->get("images");
  if (node.as_table()->get("set")) r.fail(node.as_table()->get("set"), "set", "an images entry shows another renderer's pictures: it has no settings");
  if (images->size() < 5 || images->substr(images->size() - 4) != ".png")
    r.fail(where, "images", "expected a PNG path template such as \"renders/{scene}-{view}.png\"");
  static const std::regex placeholder(R"(\{([^{}]*)\})");
  for (auto it = std::sregex_iterator(images->begin(), images->end(), placeholder); it != std::sregex_iterator(); ++it)
    if ((*it)[1] != "scene" && (*it)[1] != "view") r.fail(where, "images", "unknown placeholder " + (*it)[0].str() + " (known: {scene}, {view})");
  style.images = *images;
}

StyleEntry parseStyle(const TableReader& set, const toml::node& node, std::size_t index) {
  const std::string key = "styles[" + std::to_string(index) + "]";
  StyleEntry style;
  style.place = {set.file(), int(node.source().begin.line), set.field(key)};
  if (node.is_string()) {
    style.name = node.as_string()->get();
  } else if (node.is_table()) {
    const TableReader r(*node.as_table(), set.file(), set.field(key));
    r.allowOnly({"name", "set", "images"});
    const auto name = r.text("name");
    if (!name || name->empty()) r.fail(&node, "name", "missing");
    style.name = *name;
    readImages(r, node, style);
    if (!style.images.empty()) return style;  // a name for the level, no style
    style.settings = parseSettings(r, "set", node.as_table()->get("set"));
  } else {
    set.fail(&node, key, "expected a style name, { name = ..., set = [...] } or { name = ..., images = \"renders/{scene}.png\" }");
  }
  if (render::isStyleFilePath(style.name))  // relative to the set file
    style.name = std::filesystem::absolute(std::filesystem::path(set.file()).parent_path() / style.name).lexically_normal().string();
  try {
    const render::Style& found = render::findStyle(style.name);
    found.resolve(style.settings);
    style.fileSha256 = found.fileSha256().value_or("");
  } catch (const std::exception& e) {
    set.fail(&node, key, e.what());
  }
  return style;
}

ViewEntry parseView(const TableReader& scene, const toml::node& node, std::size_t index) {
  const std::string key = "views[" + std::to_string(index) + "]";
  if (!node.is_table()) scene.fail(&node, key, "expected { azimuth = DEG, elevation = DEG } or { camera = \"eye=...\" }");
  const TableReader r(*node.as_table(), scene.file(), scene.field(key));
  r.allowOnly({"name", "azimuth", "elevation", "camera"});
  ViewEntry view;
  view.name = r.text("name").value_or("");
  view.place = {scene.file(), int(node.source().begin.line), scene.field(key)};
  view.azimuthDegrees = r.number("azimuth").value_or(0.0);
  view.elevationDegrees = r.number("elevation").value_or(0.0);
  if (view.elevationDegrees < -89.0 || view.elevationDegrees > 89.0) r.fail(node.as_table()->get("elevation"), "elevation", "must be within [-89, 89]");
  view.camera = r.text("camera").value_or("");
  return view;
}

ProbeSetEntry parseProbeSet(const TableReader& scene, const toml::node& node, std::size_t index, std::uint64_t setSeed) {
  const std::string key = "probes[" + std::to_string(index) + "]";
  if (!node.is_table()) scene.fail(&node, key, "expected a table");
  const TableReader r(*node.as_table(), scene.file(), scene.field(key));
  r.allowOnly({"task", "count", "seed", "settings"});
  ProbeSetEntry entry;
  entry.place = r.place("task");
  const auto task = r.text("task");
  if (!task) r.fail(&node, "task", "missing (a task name, or \"points\" for labelled points)");
  entry.spec.task = *task;
  entry.spec.count = int(r.integer("count", 1, 1000).value_or(1));
  entry.spec.seed = std::uint64_t(r.integer("seed", 0, std::int64_t(1) << 53).value_or(std::int64_t(setSeed * 1000 + index + 1)));
  entry.spec.settings = r.strings("settings");
  return entry;
}

SceneEntry parseScene(const TableReader& root, const toml::node& node, std::size_t index, std::uint64_t setSeed) {
  const std::string key = "scene[" + std::to_string(index) + "]";
  if (!node.is_table()) root.fail(&node, key, "expected a table ([[scene]])");
  const TableReader r(*node.as_table(), root.file(), key);
  r.allowOnly({"source", "name", "views", "probes"});
  SceneEntry scene;
  scene.place = r.place("source");
  scene.name = r.text("name").value_or("");
  const auto source = r.text("source");
  if (!source) r.fail(&node, "source", "missing (builtin:NAME?... or a glTF file)");
  scene.source = *source;
  if (const auto* views = r.array("views"))
    for (std::size_t i = 0; i < views->size(); ++i) scene.views.push_back(parseView(r, *views->get(i), i));
  if (scene.views.empty()) scene.views.push_back(ViewEntry{"", 0.0, 0.0, "", scene.place});
  if (const auto* probes = r.array("probes"))
    for (std::size_t i = 0; i < probes->size(); ++i) scene.probeSets.push_back(parseProbeSet(r, *probes->get(i), i, setSeed));
  return scene;
}

}  // namespace

StimulusSetSpec parseStimulusSet(const std::string& text, const std::string& fileName) {
  toml::table root;
  try {
    root = toml::parse(text, fileName);
  } catch (const toml::parse_error& e) {
    throw StimulusSetError(fileName + ":" + core::tomlSyntaxMessage(text, e.source().begin.line, e.description()));
  }
  const TableReader top(root, fileName, "");
  top.allowOnly({"set", "scene"});
  const toml::node* setNode = root.get("set");
  if (!setNode || !setNode->is_table()) throw StimulusSetError(fileName + ":1: set: missing the [set] table");
  const TableReader set(*setNode->as_table(), fileName, "set");
  set.allowOnly({"name", "size", "seed", "styles", "booklet", "instructions"});
  StimulusSetSpec spec;
  spec.file = fileName;
  spec.name = set.text("name").value_or("stimuli");
  if (const auto size = set.text("size")) {
    static const std::regex pattern(R"(^(\d{1,5})x(\d{1,5})$)");
    std::smatch m;
    if (!std::regex_match(*size, m, pattern)) set.fail(setNode->as_table()->get("size"), "size", "expected WxH, got '" + *size + "'");
    spec.width = std::stoi(m[1]);
    spec.height = std::stoi(m[2]);
    if (spec.width < 16 || spec.height < 16 || spec.width > 8192 || spec.height > 8192)
      set.fail(setNode->as_table()->get("size"), "size", *size + " is outside 16x16 .. 8192x8192");
  }
  spec.seed = std::uint64_t(set.integer("seed", 0, std::int64_t(1) << 53).value_or(1));
  spec.booklet = set.boolean("booklet").value_or(true);
  spec.questionPrefix = set.text("instructions").value_or("");
  const auto* styles = set.array("styles");
  if (!styles || styles->empty()) set.fail(setNode, "styles", "missing: list at least one style");
  for (std::size_t i = 0; i < styles->size(); ++i) spec.styles.push_back(parseStyle(set, *styles->get(i), i));
  const toml::node* scenes = root.get("scene");
  if (!scenes || !scenes->is_array() || scenes->as_array()->empty())
    throw StimulusSetError(fileName + ":" + std::to_string(root.source().begin.line) + ": scene: missing: add at least one [[scene]]");
  for (std::size_t i = 0; i < scenes->as_array()->size(); ++i) spec.scenes.push_back(parseScene(top, *scenes->as_array()->get(i), i, spec.seed));
  return spec;
}

StimulusSetSpec readStimulusSetFile(const std::string& path) {
  const auto text = core::readFileText(path);
  if (!text) throw StimulusSetError(path + ": cannot read the stimulus-set file");
  return parseStimulusSet(*text, path);
}

}  // namespace tlab::stimuli
