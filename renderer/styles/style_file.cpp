// Reads a style file's declarations (style_file.hpp) and checks every field before anything is
// compiled, so a mistake in the declarations is one line naming the file, the line and the field.
#include "renderer/styles/style_file.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <regex>
#include <set>
#include <stdexcept>

#include <toml++/toml.h>

#include "core/file_text.hpp"
#include "core/sha256.hpp"

namespace tlab::render {

namespace {

const char* const kOpening = "/* tlab style";

struct Header {
  std::string toml;
  int firstLine = 1;  // the file's line of the TOML's first line
};

int lineOf(const std::string& text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

Header findHeader(const StyleFile& f) {
  const auto open = f.text.find(kOpening);
  const auto firstCode = f.text.find_first_not_of(" \t\r\n");
  if (open == std::string::npos || open != firstCode)
    throw std::invalid_argument(f.at(1, "a style file starts with its declarations: a `" + std::string(kOpening) +
                                            "` comment holding name, description, properties and parameters (TOML), then `*/`"));
  const auto body = f.text.find('\n', open);
  const auto close = f.text.find("*/", open);
  if (close == std::string::npos || body == std::string::npos || body > close)
    throw std::invalid_argument(f.at(lineOf(f.text, open), "the declarations comment is not closed by `*/` on a line of its own"));
  return {f.text.substr(body + 1, close - body - 1), lineOf(f.text, body + 1)};
}

class DeclarationReader {
 public:
  DeclarationReader(const StyleFile& file, int firstLine) : file_(file), firstLine_(firstLine) {}

  [[noreturn]] void fail(const toml::node* node, const std::string& field, const std::string& message) const {
    const int line = node ? firstLine_ + static_cast<int>(node->source().begin.line) - 1 : firstLine_;
    throw std::invalid_argument(file_.at(line, field + ": " + message));
  }
  int line(const toml::node* node) const { return node ? firstLine_ + static_cast<int>(node->source().begin.line) - 1 : firstLine_; }

  void checkKeys(const toml::table& t, const std::string& where, const std::set<std::string>& allowed) const {
    for (auto&& [key, value] : t) {
      if (allowed.count(std::string(key.str()))) continue;
      std::string known;
      for (const auto& k : allowed) known += (known.empty() ? "" : ", ") + k;
      fail(&value, (where.empty() ? "" : where + ".") + std::string(key.str()), "unknown key (known: " + known + ")");
    }
  }

  std::string string(const toml::table& t, const std::string& key, const std::string& where, bool required) const {
    const toml::node* n = t.get(key);
    if (!n) {
      if (required) fail(&t, where + key, "missing (a string is required)");
      return "";
    }
    if (!n->is_string()) fail(n, where + key, "must be a string");
    return n->as_string()->get();
  }

  // A finite number (TOML's nan and inf are numbers to the parser, not to a parameter).
  double number(const toml::node* n, const std::string& field) const {
    if (!n || !(n->is_integer() || n->is_floating_point())) fail(n, field, "must be a number");
    const double v = n->is_integer() ? double(n->as_integer()->get()) : n->as_floating_point()->get();
    if (!std::isfinite(v)) fail(n, field, "must be a finite number");
    return v;
  }

 private:
  const StyleFile& file_;
  int firstLine_;
};

const std::regex kIdentifier(R"(^[a-z][a-z0-9_]*$)");
const std::set<std::string> kReserved = {"lighting", "iterations"};

StyleParameter readParameter(const DeclarationReader& r, const toml::table& t, const std::string& where) {
  r.checkKeys(t, where, {"name", "type", "default", "range", "description"});
  StyleParameter p;
  p.line = r.line(&t);
  const std::string name = r.string(t, "name", where + ".", true);
  if (!std::regex_match(name, kIdentifier) || name.rfind("gl_", 0) == 0)
    r.fail(t.get("name"), where + ".name", "'" + name + "' is not a lower-case GLSL identifier (a-z, 0-9, _)");
  if (kReserved.count(name)) r.fail(t.get("name"), where + ".name", "'" + name + "' is tlab's own parameter");
  const std::string type = r.string(t, "type", where + ".", true);
  const std::string help = r.string(t, "description", where + ".", true);
  const toml::node* def = t.get("default");
  if (!def) r.fail(&t, where + ".default", "missing");
  if (type == "bool") {
    if (!def->is_boolean()) r.fail(def, where + ".default", "must be true or false");
    if (t.get("range")) r.fail(t.get("range"), where + ".range", "a bool has no range");
    p.type = StyleValueType::Bool;
    p.spec = ParamSpec::choice(name, def->as_boolean()->get() ? "true" : "false", {"true", "false"}, help);
    return p;
  }
  if (type != "float" && type != "int") r.fail(t.get("type"), where + ".type", "expected \"float\", \"int\" or \"bool\", got '" + type + "'");
  p.type = type == "int" ? StyleValueType::Int : StyleValueType::Float;
  const toml::array* range = t.get("range") ? t.get("range")->as_array() : nullptr;
  if (!range || range->size() != 2) r.fail(t.get("range") ? t.get("range") : &t, where + ".range", "expected [min, max]");
  const double lo = r.number(range->get(0), where + ".range"), hi = r.number(range->get(1), where + ".range");
  const double value = r.number(def, where + ".default");
  if (!(lo <= hi)) r.fail(range, where + ".range", "min is above max");
  if (value < lo || value > hi) r.fail(def, where + ".default", "outside its range");
  if (p.type == StyleValueType::Int && (!def->is_integer() || std::floor(lo) != lo || std::floor(hi) != hi))
    r.fail(def, where + ".default", "an int parameter takes whole numbers (default and range)");
  // The parameter is a GLSL uniform: every value of its range must fit its type (an int's 32
  // bits; a float's finite range, beyond which a value would arrive as infinity).
  if (p.type == StyleValueType::Int && (lo < double(std::numeric_limits<std::int32_t>::min()) ||
                                        hi > double(std::numeric_limits<std::int32_t>::max())))
    r.fail(range, where + ".range", "an int parameter's range lies within [-2147483648, 2147483647] (a GLSL int)");
  const double floatMax = std::numeric_limits<float>::max();
  if (p.type == StyleValueType::Float && (lo < -floatMax || hi > floatMax))
    r.fail(range, where + ".range", "a float parameter's range lies within [-3.40282e+38, 3.40282e+38] (a GLSL float)");
  p.spec = ParamSpec::number(name, value, lo, hi, help);
  return p;
}

StyleDeclaration readDeclaration(const StyleFile& f, const Header& h) {
  const DeclarationReader r(f, h.firstLine);
  toml::table root;
  try {
    root = toml::parse(h.toml);
  } catch (const toml::parse_error& e) {
    throw std::invalid_argument(f.at(h.firstLine + static_cast<int>(e.source().begin.line) - 1,
                                     "declarations: " + std::string(e.description())));
  }
  r.checkKeys(root, "", {"name", "description", "properties", "neighbors", "iterations", "parameter"});
  StyleDeclaration d;
  d.name = r.string(root, "name", "", true);
  if (d.name.empty()) r.fail(root.get("name"), "name", "must not be empty");
  d.description = r.string(root, "description", "", true);
  if (const toml::node* n = root.get("properties")) {
    const toml::array* a = n->as_array();
    if (!a) r.fail(n, "properties", "must be an array of property names");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::node* p = a->get(i);
      const std::string field = "properties[" + std::to_string(i + 1) + "]";
      if (!p->is_string()) r.fail(p, field, "must be a string");
      try {
        d.properties |= parsePropertyName(p->as_string()->get());
      } catch (const std::invalid_argument& e) {
        r.fail(p, field, e.what());
      }
    }
  }
  if (const toml::node* n = root.get("neighbors")) {
    if (!n->is_boolean()) r.fail(n, "neighbors", "must be true or false");
    d.neighbors = n->as_boolean()->get();
  }
  if (const toml::node* n = root.get("iterations")) {
    const double v = r.number(n, "iterations");
    if (!d.neighbors) r.fail(n, "iterations", "only a style with neighbors = true iterates");
    if (!n->is_integer() || v < 0 || v > 10000) r.fail(n, "iterations", "a whole number in [0, 10000]");
    d.iterations = static_cast<int>(v);
  }
  if (const toml::node* n = root.get("parameter")) {
    const toml::array* a = n->as_array();
    if (!a || !a->is_array_of_tables()) r.fail(n, "parameter", "declare each parameter as a [[parameter]] table");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string where = "parameter[" + std::to_string(i + 1) + "]";
      StyleParameter p = readParameter(r, *a->get(i)->as_table(), where);
      for (const auto& q : d.parameters)
        if (q.spec.name == p.spec.name) r.fail(a->get(i)->as_table()->get("name"), where + ".name", "'" + q.spec.name + "' is declared twice");
      d.parameters.push_back(std::move(p));
    }
  }
  return d;
}

}  // namespace

FragmentProperty parsePropertyName(const std::string& name) {
  static const std::vector<std::pair<std::string, FragmentProperty>> names = {
      {"color", FragmentProperty::Color},           {"normal", FragmentProperty::Normal},
      {"depth_gradient", FragmentProperty::DepthGradient}, {"ids", FragmentProperty::Ids},
      {"st", FragmentProperty::SurfaceParams},      {"nz_gradient", FragmentProperty::NormalZGradient},
      {"st_gradient", FragmentProperty::StGradient}};
  std::string known;
  for (const auto& [n, p] : names) {
    if (n == name) return p;
    known += (known.empty() ? "" : ", ") + n;
  }
  throw std::invalid_argument("unknown fragment property '" + name + "' (known: " + known + "; depth is always there)");
}

bool isStyleFilePath(const std::string& style) {
  return style.size() > 5 && style.compare(style.size() - 5, 5, ".glsl") == 0;
}

std::string StyleFile::at(int line, const std::string& message) const { return path + ":" + std::to_string(line) + ": " + message; }

std::vector<ParamSpec> StyleFile::params() const {
  std::vector<ParamSpec> specs;
  for (const auto& p : declaration.parameters) specs.push_back(p.spec);
  if (declaration.neighbors)
    specs.push_back(ParamSpec::number("iterations", declaration.iterations, 0, 10000,
                                      "iterations N of the per-fragment stage over the linked neighbours"));
  return specs;
}

StyleProgram StyleFile::program(const StyleParams& params) const {
  StyleProgram p{path, sha256, text, {}};
  for (const auto& d : declaration.parameters) {
    const double value = d.type == StyleValueType::Bool ? (params.is(d.spec.name, "true") ? 1.0 : 0.0) : params.number(d.spec.name);
    p.uniforms.push_back({d.spec.name, d.type, value});
  }
  return p;
}

StyleFile parseStyleFile(const std::string& path, std::string text) {
  StyleFile f;
  f.path = path;
  f.text = std::move(text);
  f.sha256 = core::sha256Hex(f.text);
  const Header header = findHeader(f);
  f.declaration = readDeclaration(f, header);
  const auto version = f.text.find("#version");
  if (version != std::string::npos)
    throw std::invalid_argument(f.at(lineOf(f.text, version), "#version: tlab supplies it (450 core); remove the line"));
  return f;
}

StyleFile loadStyleFile(const std::string& path) {
  const auto text = core::readFileText(path);
  if (!text) throw std::invalid_argument("cannot read style file '" + path + "'");
  return parseStyleFile(path, *text);
}

}  // namespace tlab::render
