#pragma once
// Style parameters: one map filled by `--set key=value`, validated against the keys a style
// declares (name, kind, default, range or choices). Errors name the style and the key.
#include <map>
#include <string>
#include <vector>

namespace tlab::render {

struct ParamSpec {
  enum class Kind { Number, Choice, Text };
  std::string name;
  Kind kind = Kind::Number;
  std::string defaultValue;
  double minValue = 0.0, maxValue = 0.0;  // Number: the allowed closed range
  std::vector<std::string> choices;       // Choice: the allowed words
  std::string help;

  static ParamSpec number(std::string name, double def, double lo, double hi, std::string help);
  static ParamSpec choice(std::string name, std::string def, std::vector<std::string> choices, std::string help);
  // Free text (a file name or an inline specification the style parses in validate()).
  static ParamSpec text(std::string name, std::string def, std::string help);
};

// Validated parameters of one style: every declared key has a value (given or default).
class StyleParams {
 public:
  StyleParams() = default;
  // `given` holds raw key=value pairs; throws std::invalid_argument on unknown keys, values that
  // do not parse, or values out of range.
  StyleParams(const std::string& styleName, const std::vector<ParamSpec>& specs,
              const std::map<std::string, std::string>& given);
  double number(const std::string& key) const;
  const std::string& choice(const std::string& key) const;
  const std::string& text(const std::string& key) const { return choice(key); }
  bool is(const std::string& key, const std::string& word) const { return choice(key) == word; }
  const std::map<std::string, std::string>& values() const { return values_; }

 private:
  std::map<std::string, std::string> values_;
  std::map<std::string, double> numbers_;
};

// Parses "key=value" (as given to --set) into the map; throws on a missing '='.
void addSetting(std::map<std::string, std::string>& settings, const std::string& keyValue);

}  // namespace tlab::render
