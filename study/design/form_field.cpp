#include "study/design/form_field.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>


namespace tlab::study {

namespace {

std::optional<double> parseNumber(const std::string& text) {
  std::istringstream in(text);
  double v = 0;
  char extra = 0;
  if (!(in >> v) || (in >> extra) || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string numberText(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

std::string fieldError(const FormField& f, const std::string& value) {
  if (value.empty()) return f.required || f.kind == FieldKind::Likert ? "an answer is required" : "";
  switch (f.kind) {
    case FieldKind::Likert: {
      const auto v = parseNumber(value);
      if (!v || *v != std::floor(*v) || *v < 1 || *v > f.points) return "choose a value from 1 to " + std::to_string(f.points);
      return "";
    }
    case FieldKind::Choice:
      return std::find(f.options.begin(), f.options.end(), value) == f.options.end() ? "choose one of the options" : "";
    case FieldKind::Number: {
      const auto v = parseNumber(value);
      if (!v) return "'" + value + "' is not a number";
      if (f.integer && *v != std::floor(*v)) return "a whole number is required";
      if (*v < f.minimum || *v > f.maximum) return "a number from " + numberText(f.minimum) + " to " + numberText(f.maximum) + " is required";
      return "";
    }
    case FieldKind::Text:
      return value.size() > 10000 ? "at most 10000 characters" : "";
  }
  return "";
}

std::optional<double> fieldNumber(const FormField& f, const std::string& value) {
  if (value.empty() || !fieldError(f, value).empty()) return std::nullopt;
  if (f.kind == FieldKind::Choice) return double(std::find(f.options.begin(), f.options.end(), value) - f.options.begin() + 1);
  if (f.kind == FieldKind::Text) return std::nullopt;
  return parseNumber(value);
}

std::string fieldHint(const FormField& f) {
  switch (f.kind) {
    case FieldKind::Likert:
      return "Press or click 1 (" + f.lowAnchor + ") to " + std::to_string(f.points) + " (" + f.highAnchor + ").";
    case FieldKind::Choice: return "Press the number of your choice or click it.";
    case FieldKind::Number:
      return "Type a " + std::string(f.integer ? "whole " : "") + "number from " + numberText(f.minimum) + " to " + numberText(f.maximum) +
             " and press Enter.";
    case FieldKind::Text: return std::string("Type your answer and press Enter") + (f.required ? "." : " (Enter alone: no answer).");
  }
  return "";
}

}  // namespace tlab::study
