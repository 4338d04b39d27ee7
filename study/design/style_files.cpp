#include "study/design/style_files.hpp"

#include <filesystem>
#include <regex>
#include <sstream>

#include "core/file_text.hpp"
#include "core/sha256.hpp"
#include "renderer/styles/style_file.hpp"

namespace tlab::study {

namespace {

const char* const kRecord = "# tlab style file ";

// The identities a stored text already records, by the path as written.
std::map<std::string, StyleFileUse> recordedUses(const std::string& text) {
  static const std::regex line(R"(^# tlab style file (.+) = (.+) sha256 ([0-9a-f]{64})\r?$)");
  std::map<std::string, StyleFileUse> uses;
  std::istringstream lines(text);
  for (std::string l; std::getline(lines, l);) {
    std::smatch m;
    if (std::regex_match(l, m, line)) uses[m[1]] = {m[1], m[2], m[3]};
  }
  return uses;
}

class Resolver {
 public:
  Resolver(const FieldReader& r, Experiment& e, bool readFiles)
      : r_(r), e_(e), readFiles_(readFiles), recorded_(recordedUses(e.text)) {}

  void resolve(std::string& style, const toml::node* node, const std::string& field) {
    if (!render::isStyleFilePath(style)) return;
    for (const auto& u : e_.styleFiles)
      if (u.written == style) {
        style = u.path;
        return;
      }
    StyleFileUse use;
    if (const auto it = recorded_.find(style); it != recorded_.end()) {
      use = it->second;
    } else {
      namespace fs = std::filesystem;
      use.written = style;
      use.path = fs::absolute(fs::path(e_.path).parent_path() / style).lexically_normal().string();
      const auto text = core::readFileText(use.path);
      if (!text && readFiles_) r_.fail(node, field, "cannot read the style file '" + use.path + "' (paths are relative to the experiment file)");
      if (text) use.sha256 = core::sha256Hex(*text);
      unrecorded_ = true;
    }
    style = use.path;
    e_.styleFiles.push_back(use);
  }

  void record() {
    if (!unrecorded_) return;
    std::string trailer = e_.text.empty() || e_.text.back() == '\n' ? "" : "\n";
    for (const auto& u : e_.styleFiles) trailer += kRecord + u.written + " = " + u.path + " sha256 " + u.sha256 + "\n";
    e_.text += trailer;
  }

 private:
  const FieldReader& r_;
  Experiment& e_;
  bool readFiles_;
  std::map<std::string, StyleFileUse> recorded_;
  bool unrecorded_ = false;
};

const toml::node* child(const toml::node* n, const char* key) { return n && n->as_table() ? n->as_table()->get(key) : nullptr; }

}  // namespace

void resolveStyleFiles(const FieldReader& r, const toml::table& root, Experiment& e, bool readFiles) {
  Resolver resolver(r, e, readFiles);
  resolver.resolve(e.stimulus.style, child(root.get("stimulus"), "style"), "stimulus.style");
  const toml::array* factors = root.get("factors") ? root.get("factors")->as_array() : nullptr;
  for (std::size_t f = 0; f < e.factors.size(); ++f) {
    const toml::array* levels = factors && factors->get(f) ? child(factors->get(f), "levels") ? child(factors->get(f), "levels")->as_array() : nullptr : nullptr;
    for (std::size_t l = 0; l < e.factors[f].levels.size(); ++l) {
      auto& style = e.factors[f].levels[l].style;
      if (!style) continue;
      const std::string field = "factors[" + std::to_string(f + 1) + "].levels[" + std::to_string(l + 1) + "].style";
      resolver.resolve(*style, levels ? child(levels->get(l), "style") : nullptr, field);
    }
  }
  resolver.record();
}

std::string styleIdentity(const Experiment& e, const std::string& style) {
  for (const auto& u : e.styleFiles)
    if (u.path == style) return "file sha256:" + u.sha256;
  return style;
}

}  // namespace tlab::study
