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

}  // namespace

std::string fieldError(const FormField& f, const std::string& value, const ParticipantTexts& texts) {
  if (value.empty()) return f.required || f.kind == FieldKind::Likert ? texts.text("form.required") : "";
  switch (f.kind) {
    case FieldKind::Likert: {
      const auto v = parseNumber(value);
      if (!v || *v != std::floor(*v) || *v < 1 || *v > f.points) return texts.format("form.likert_range", {{"points", std::to_string(f.points)}});
      return "";
    }
    case FieldKind::Choice:
      return std::find(f.options.begin(), f.options.end(), value) == f.options.end() ? texts.text("form.choose_option") : "";
    case FieldKind::Number: {
      const auto v = parseNumber(value);
      if (!v) return texts.format("form.not_number", {{"value", value}});
      if (f.integer && *v != std::floor(*v)) return texts.text("form.whole_number");
      if (*v < f.minimum || *v > f.maximum)
        return texts.format("form.number_range", {{"min", texts.number(f.minimum)}, {"max", texts.number(f.maximum)}});
      return "";
    }
    case FieldKind::Text:
      return value.size() > 10000 ? texts.text("form.too_long") : "";
  }
  return "";
}

std::optional<double> fieldNumber(const FormField& f, const std::string& value) {
  if (value.empty() || !fieldError(f, value).empty()) return std::nullopt;
  if (f.kind == FieldKind::Choice) return double(std::find(f.options.begin(), f.options.end(), value) - f.options.begin() + 1);
  if (f.kind == FieldKind::Text) return std::nullopt;
  return parseNumber(value);
}

std::string fieldHint(const FormField& f, const ParticipantTexts& texts) {
  switch (f.kind) {
    case FieldKind::Likert:
      return texts.format("form.hint_likert", {{"low", f.lowAnchor}, {"high", f.highAnchor}, {"points", std::to_string(f.points)}});
    case FieldKind::Choice: return texts.text("form.hint_choice");
    case FieldKind::Number:
      return texts.format(f.integer ? "form.hint_whole_number" : "form.hint_number", {{"min", texts.number(f.minimum)}, {"max", texts.number(f.maximum)}});
    case FieldKind::Text: return texts.text(f.required ? "form.hint_text" : "form.hint_text_optional");
  }
  return "";
}

}  // namespace tlab::study
