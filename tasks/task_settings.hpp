#pragma once
// A task's settings: declared keys with defaults and help, filled from "key=value" strings
// (`--set` on the command line, a table in an experiment file) and validated against the keys.
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace tlab::tasks {

struct SettingSpec {
  std::string key;
  std::string defaultValue;
  std::string help;
  bool numeric = true;
  // A numeric setting's allowed closed range, and whether it takes whole numbers only (a count,
  // a layer): what the task can use, checked where the value is given (--set, an experiment file).
  double minValue = -std::numeric_limits<double>::max();
  double maxValue = std::numeric_limits<double>::max();
  bool whole = false;

  static SettingSpec number(std::string key, std::string def, std::string help, double lo, double hi);
  static SettingSpec count(std::string key, std::string def, std::string help, double lo, double hi);  // whole
  static SettingSpec text(std::string key, std::string def, std::string help);
  // "a whole number in [1, 1000000]", "a number in [0, 1]", or "" (text).
  std::string rangeText() const;
};

class TaskSettings {
 public:
  // Throws std::invalid_argument naming an unknown key (and listing the known ones), a
  // non-numeric value for a numeric key, or a number outside its range or not whole where it must be.
  TaskSettings(const std::string& taskName, const std::vector<SettingSpec>& specs,
               const std::vector<std::string>& assignments = {});

  double number(const std::string& key) const;
  const std::string& text(const std::string& key) const;
  const std::map<std::string, std::string>& values() const { return values_; }

 private:
  std::string taskName_;
  std::map<std::string, std::string> values_;
};

// The settings every task has: the per-question time limit (Carnecky Sec. 8: two minutes).
std::vector<SettingSpec> commonSettings();

}  // namespace tlab::tasks
