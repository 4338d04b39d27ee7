#pragma once
// FieldReader: reads typed fields of an experiment file's TOML tables and fails with one line
// naming the file, the line and the dotted field ("study.toml:12: tasks[2].trials: must be >= 1").
// Shared by the parsers of the experiment file's sections.
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "core/parse_number.hpp"
#include "study/design/experiment_file.hpp"

namespace tlab::study {

// Where a field is: the file, the line of its node, and its dotted name.
class FieldReader {
 public:
  explicit FieldReader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const toml::node* node, const std::string& field, const std::string& message) const {
    throw ExperimentFileError(at(node, field) + ": " + message);
  }

  // "file:line: field", for checks made later (an online run refusing a walking task).
  std::string at(const toml::node* node, const std::string& field) const {
    const auto line = node ? node->source().begin.line : 0u;
    return path_ + ":" + std::to_string(line) + ": " + field;
  }

  void checkKeys(const toml::table& table, const std::string& where, const std::set<std::string>& allowed) const {
    for (auto&& [key, value] : table) {
      if (allowed.count(std::string(key.str()))) continue;
      std::string known;
      for (const auto& k : allowed) known += (known.empty() ? "" : ", ") + k;
      fail(&value, where.empty() ? std::string(key.str()) : where + "." + std::string(key.str()),
           "unknown key (known: " + known + ")");
    }
  }

  std::string string(const toml::table& t, const std::string& key, const std::string& where, bool required,
                     const std::string& fallback = "") const {
    const toml::node* n = t.get(key);
    if (!n) {
      if (required) fail(&t, name(where, key), "missing (a string is required)");
      return fallback;
    }
    if (!n->is_string()) fail(n, name(where, key), "must be a string");
    return n->as_string()->get();
  }

  std::int64_t integer(const toml::table& t, const std::string& key, const std::string& where, std::int64_t fallback,
                       std::int64_t minimum, bool required = false) const {
    const toml::node* n = t.get(key);
    if (!n) {
      if (required) fail(&t, name(where, key), "missing (an integer is required)");
      return fallback;
    }
    if (!n->is_integer()) fail(n, name(where, key), "must be an integer");
    const std::int64_t v = n->as_integer()->get();
    if (v < minimum) fail(n, name(where, key), "must be >= " + std::to_string(minimum));
    return v;
  }

  double number(const toml::table& t, const std::string& key, const std::string& where, double fallback, double minimum,
                double maximum) const {
    const toml::node* n = t.get(key);
    if (!n) return fallback;
    double v;
    if (n->is_integer()) v = double(n->as_integer()->get());
    else if (n->is_floating_point()) v = n->as_floating_point()->get();
    else fail(n, name(where, key), "must be a number");
    if (!(v >= minimum && v <= maximum))
      fail(n, name(where, key), "must be within [" + core::roundTripText(minimum) + ", " + core::roundTripText(maximum) + "]");
    return v;
  }

  std::vector<std::string> strings(const toml::table& t, const std::string& key, const std::string& where) const {
    std::vector<std::string> out;
    const toml::node* n = t.get(key);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a) fail(n, name(where, key), "must be an array of strings");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::node& e = *a->get(i);
      if (!e.is_string()) fail(&e, name(where, key) + "[" + std::to_string(i + 1) + "]", "must be a string");
      out.push_back(e.as_string()->get());
    }
    return out;
  }

  const toml::table* table(const toml::table& t, const std::string& key, const std::string& where) const {
    const toml::node* n = t.get(key);
    if (!n) return nullptr;
    if (!n->is_table()) fail(n, name(where, key), "must be a table");
    return n->as_table();
  }

  // An array of tables ([[key]]); empty when absent.
  std::vector<const toml::table*> tables(const toml::table& t, const std::string& key) const {
    std::vector<const toml::table*> out;
    const toml::node* n = t.get(key);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a) fail(n, key, "must be an array of tables ([[" + key + "]])");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::node& e = *a->get(i);
      if (!e.is_table()) fail(&e, key + "[" + std::to_string(i + 1) + "]", "must be a table");
      out.push_back(e.as_table());
    }
    return out;
  }

  static std::string name(const std::string& where, const std::string& key) { return where.empty() ? key : where + "." + key; }

 private:
  std::string path_;
};

}  // namespace tlab::study
