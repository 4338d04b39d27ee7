#include "renderer/params/style_params.hpp"

#include <cmath>
#include <stdexcept>

#include "core/parse_number.hpp"

namespace tlab::render {

ParamSpec ParamSpec::number(std::string name, double def, double lo, double hi, std::string help) {
  ParamSpec s;
  s.name = std::move(name);
  s.kind = Kind::Number;
  s.defaultValue = core::roundTripText(def);  // the declared number, every digit of it
  s.minValue = lo;
  s.maxValue = hi;
  s.help = std::move(help);
  return s;
}

ParamSpec ParamSpec::choice(std::string name, std::string def, std::vector<std::string> choices, std::string help) {
  ParamSpec s;
  s.name = std::move(name);
  s.kind = Kind::Choice;
  s.defaultValue = std::move(def);
  s.choices = std::move(choices);
  s.help = std::move(help);
  return s;
}

ParamSpec ParamSpec::text(std::string name, std::string def, std::string help) {
  ParamSpec s;
  s.name = std::move(name);
  s.kind = Kind::Text;
  s.defaultValue = std::move(def);
  s.help = std::move(help);
  return s;
}

namespace {

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

double parseNumber(const std::string& style, const ParamSpec& spec, const std::string& text) {
  const auto parsed = core::parseFiniteNumber(text);
  if (!parsed)
    throw std::invalid_argument("style '" + style + "' parameter '" + spec.name + "': '" + text + "' is not a number");
  const double v = *parsed;
  if (v < spec.minValue || v > spec.maxValue) {
    throw std::invalid_argument("style '" + style + "' parameter '" + spec.name + "' = " + text + " is outside [" +
                                core::roundTripText(spec.minValue) + ", " + core::roundTripText(spec.maxValue) + "]");
  }
  return v;
}

}  // namespace

StyleParams::StyleParams(const std::string& style, const std::vector<ParamSpec>& specs,
                         const std::map<std::string, std::string>& given) {
  for (const auto& [key, value] : given) {
    bool known = false;
    for (const auto& s : specs) known = known || s.name == key;
    if (!known) {
      std::vector<std::string> names;
      for (const auto& s : specs) names.push_back(s.name);
      throw std::invalid_argument("style '" + style + "' has no parameter '" + key + "'" +
                                  (names.empty() ? " (it takes none)" : " (known: " + joined(names) + ")"));
    }
  }
  for (const auto& spec : specs) {
    const auto it = given.find(spec.name);
    const std::string value = it == given.end() ? spec.defaultValue : it->second;
    if (spec.kind == ParamSpec::Kind::Number) {
      numbers_[spec.name] = parseNumber(style, spec, value);
    } else if (spec.kind == ParamSpec::Kind::Choice) {
      bool ok = false;
      for (const auto& c : spec.choices) ok = ok || c == value;
      if (!ok)
        throw std::invalid_argument("style '" + style + "' parameter '" + spec.name + "': '" + value +
                                    "' is not one of " + joined(spec.choices));
    }
    values_[spec.name] = value;
  }
}

double StyleParams::number(const std::string& key) const {
  const auto it = numbers_.find(key);
  if (it == numbers_.end()) throw std::logic_error("style parameter '" + key + "' is not a declared number");
  return it->second;
}

const std::string& StyleParams::choice(const std::string& key) const {
  const auto it = values_.find(key);
  if (it == values_.end()) throw std::logic_error("style parameter '" + key + "' is not declared");
  return it->second;
}

void addSetting(std::map<std::string, std::string>& settings, const std::string& keyValue) {
  const auto eq = keyValue.find('=');
  if (eq == std::string::npos || eq == 0)
    throw std::invalid_argument("--set expects key=value, got '" + keyValue + "'");
  settings[keyValue.substr(0, eq)] = keyValue.substr(eq + 1);
}

}  // namespace tlab::render
