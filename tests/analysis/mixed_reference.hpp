#pragma once
// The reference values of reference/mixed_models.R (R 4.2.2, lme4 1.1-31, lmerTest 3.1-3,
// BayesFactor 0.9.12-4.4), read from reference/mixed/expected.csv, and a tracker of the largest
// relative difference per figure that the tests print.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <tuple>

#include "analysis/csv_reader.hpp"

namespace tlab::analysis::testing {

inline std::string referencePath(const std::string& name) {
  return std::string(TLAB_SOURCE_DIR) + "/tests/analysis/reference/mixed/" + name;
}

class MixedReference {
 public:
  MixedReference() {
    const Table t = readCsvFile(referencePath("expected.csv"));
    for (std::size_t r = 0; r < t.rowCount(); ++r)
      values_[{t.text(r, 0), t.text(r, 1), t.text(r, 2), t.text(r, 3)}] = std::stod(t.text(r, 4));
  }
  bool has(const std::string& model, const std::string& section, const std::string& name, const std::string& field) const {
    return values_.count({model, section, name, field}) > 0;
  }
  double at(const std::string& model, const std::string& section, const std::string& name, const std::string& field) const {
    const auto it = values_.find({model, section, name, field});
    if (it == values_.end()) ADD_FAILURE() << "no reference value " << model << "/" << section << "/" << name << "/" << field;
    return it == values_.end() ? std::nan("") : it->second;
  }
  // The names present for (model, section, field).
  std::vector<std::string> names(const std::string& model, const std::string& section, const std::string& field) const {
    std::vector<std::string> out;
    for (const auto& [key, value] : values_)
      if (std::get<0>(key) == model && std::get<1>(key) == section && std::get<3>(key) == field) out.push_back(std::get<2>(key));
    return out;
  }

 private:
  std::map<std::tuple<std::string, std::string, std::string, std::string>, double> values_;
};

// Collects |actual − expected| / |expected| per figure, checks each against its tolerance, and
// prints the largest per figure at the end of the test.
class RelativeDifferences {
 public:
  explicit RelativeDifferences(std::string label) : label_(std::move(label)) {}
  ~RelativeDifferences() {
    for (const auto& [figure, worst] : worst_)
      std::cout << "[ reference ] " << label_ << " " << figure << ": max relative difference " << worst << "\n";
  }
  void check(const std::string& figure, const std::string& what, double actual, double expected, double tolerance) {
    const double rel = std::fabs(actual - expected) / std::max(std::fabs(expected), 1e-300);
    worst_[figure] = std::max(worst_[figure], rel);
    EXPECT_LE(rel, tolerance) << label_ << " " << figure << " " << what << ": " << std::setprecision(17) << actual << " vs R "
                              << expected;
  }

 private:
  std::string label_;
  std::map<std::string, double> worst_;
};

}  // namespace tlab::analysis::testing
