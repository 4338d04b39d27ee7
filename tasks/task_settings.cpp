#include "tasks/task_settings.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tlab::tasks {

namespace {
bool isNumber(const std::string& s, double* value) {
  std::size_t used = 0;
  try {
    *value = std::stod(s, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == s.size() && std::isfinite(*value);
}
}  // namespace

TaskSettings::TaskSettings(const std::string& taskName, const std::vector<SettingSpec>& specs,
                           const std::vector<std::string>& assignments)
    : taskName_(taskName) {
  for (const auto& s : specs) values_[s.key] = s.defaultValue;
  for (const auto& a : assignments) {
    const auto eq = a.find('=');
    const std::string key = a.substr(0, eq);
    const auto spec = std::find_if(specs.begin(), specs.end(), [&](const SettingSpec& s) { return s.key == key; });
    if (eq == std::string::npos || spec == specs.end()) {
      std::string known;
      for (const auto& s : specs) known += (known.empty() ? "" : ", ") + s.key;
      throw std::invalid_argument("task '" + taskName + "': unknown setting '" + a + "' (expected key=value with key one of: " + known + ")");
    }
    const std::string value = a.substr(eq + 1);
    double v = 0.0;
    if (spec->numeric && !isNumber(value, &v))
      throw std::invalid_argument("task '" + taskName + "': setting '" + key + "' expects a number, got '" + value + "'");
    values_[key] = value;
  }
}

double TaskSettings::number(const std::string& key) const {
  double v = 0.0;
  const auto it = values_.find(key);
  if (it == values_.end() || !isNumber(it->second, &v))
    throw std::logic_error("task '" + taskName_ + "': no numeric setting '" + key + "'");
  return v;
}

const std::string& TaskSettings::text(const std::string& key) const {
  const auto it = values_.find(key);
  if (it == values_.end()) throw std::logic_error("task '" + taskName_ + "': no setting '" + key + "'");
  return it->second;
}

std::vector<SettingSpec> commonSettings() {
  return {{"time-limit", "120", "seconds per question; a later answer counts as missing (= wrong)", true}};
}

}  // namespace tlab::tasks
