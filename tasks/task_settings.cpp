#include "tasks/task_settings.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/parse_number.hpp"

namespace tlab::tasks {

SettingSpec SettingSpec::number(std::string key, std::string def, std::string help, double lo, double hi) {
  return {std::move(key), std::move(def), std::move(help), true, lo, hi, false};
}

SettingSpec SettingSpec::count(std::string key, std::string def, std::string help, double lo, double hi) {
  return {std::move(key), std::move(def), std::move(help), true, lo, hi, true};
}

SettingSpec SettingSpec::text(std::string key, std::string def, std::string help) {
  return {std::move(key), std::move(def), std::move(help), false};
}

namespace {
// A range end as a user types it: whole numbers in full (1000000, not 1e+06).
std::string endText(double v) {
  return std::abs(v) < 1e15 && v == std::floor(v) ? std::to_string(static_cast<long long>(v)) : core::roundTripText(v);
}
}  // namespace

std::string SettingSpec::rangeText() const {
  if (!numeric) return "";
  return std::string(whole ? "a whole number" : "a number") + " in [" + endText(minValue) + ", " + endText(maxValue) + "]";
}

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
    if (spec->numeric) {
      const auto v = core::parseFiniteNumber(value);
      const std::string named = "task '" + taskName + "': setting '" + key + "'";
      if (!v) throw std::invalid_argument(named + " expects a number, got '" + value + "'");
      if (*v < spec->minValue || *v > spec->maxValue || (spec->whole && *v != std::floor(*v)))
        throw std::invalid_argument(named + " = " + value + ": expected " + spec->rangeText());
    }
    values_[key] = value;
  }
}

double TaskSettings::number(const std::string& key) const {
  const auto it = values_.find(key);
  const auto v = it == values_.end() ? std::nullopt : core::parseFiniteNumber(it->second);
  if (!v) throw std::logic_error("task '" + taskName_ + "': no numeric setting '" + key + "'");
  return *v;
}

const std::string& TaskSettings::text(const std::string& key) const {
  const auto it = values_.find(key);
  if (it == values_.end()) throw std::logic_error("task '" + taskName_ + "': no setting '" + key + "'");
  return it->second;
}

std::vector<SettingSpec> commonSettings() {
  // The experiment file's time_limit allows the same range (study/design/experiment_file.cpp).
  return {SettingSpec::number("time-limit", "120", "seconds per question; a later answer counts as missing (= wrong)", 0.5, 86400)};
}

}  // namespace tlab::tasks
