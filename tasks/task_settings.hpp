#pragma once
// A task's settings: declared keys with defaults and help, filled from "key=value" strings
// (`--set` on the command line, a table in an experiment file) and validated against the keys.
#include <map>
#include <string>
#include <vector>

namespace tlab::tasks {

struct SettingSpec {
  std::string key;
  std::string defaultValue;
  std::string help;
  bool numeric = true;
};

class TaskSettings {
 public:
  // Throws std::invalid_argument naming an unknown key (and listing the known ones) or a
  // non-numeric value for a numeric key.
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
