#include "tasks/answer_parser.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "tasks/answer_form.hpp"
#include "tasks/letter_patterns.hpp"

namespace tlab::tasks {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

// `key`: the participant's words for the same refusal (AnswerFormatError).
[[noreturn]] void fail(const std::string& expected, const std::string& text, const std::string& key,
                       std::map<std::string, std::string> args = {}) {
  throw AnswerFormatError("answer: expected " + expected + ", got '" + text + "'", key, std::move(args));
}

std::int64_t parseWhole(const std::string& text, std::int64_t minimum, const std::string& expected, const std::string& key) {
  const std::string t = trim(text);
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size() || v < minimum) fail(expected, text, key);
  return v;
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::toupper(c)); });
  return s;
}

// Labels are matched case-insensitively and reported in the question's spelling.
std::string findLabel(const std::string& token, const std::vector<std::string>& allowed, const std::string& text) {
  for (const auto& a : allowed)
    if (upper(a) == upper(token)) return a;
  throw AnswerFormatError("answer: '" + token + "' in '" + text + "' is not one of the labels (" + joined(allowed) + ")",
                          "refusal.not_a_label", {{"label", token}, {"labels", joined(allowed)}});
}

double parseNumber(const std::string& s, const std::string& text, const std::string& expected, const std::string& key) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != s.size() || !std::isfinite(v)) fail(expected, text, key);
  return v;
}

const char* const kFloorPoint = "a floor-plan point 'X,Z' in world units";
double parseReal(const std::string& s, const std::string& text) { return parseNumber(s, text, kFloorPoint, "refusal.floor_point"); }

}  // namespace

std::int64_t parseLayerNumber(const std::string& text) {
  return parseWhole(text, 1, "a layer number (a whole number >= 1, 1 = front)", "refusal.layer_number");
}

std::int64_t parseCount(const std::string& text) { return parseWhole(text, 0, "a count (a whole number >= 0)", "refusal.count"); }

std::set<std::string> parseLabelSet(const std::string& text, const std::vector<std::string>& allowed) {
  std::string t = trim(text);
  if (t.empty() || upper(t) == "NONE" || t == "-") return {};
  std::replace(t.begin(), t.end(), ',', ' ');
  std::istringstream in(t);
  std::set<std::string> out;
  std::string token;
  while (in >> token)
    if (!out.insert(findLabel(token, allowed, text)).second)
      throw AnswerFormatError("answer: label '" + token + "' appears twice in '" + text + "'", "refusal.label_twice", {{"label", token}});
  return out;
}

std::string parseLabel(const std::string& text, const std::vector<std::string>& allowed) {
  const std::string t = trim(text);
  if (t.empty() || t.find_first_of(" ,\t") != std::string::npos)
    fail("one label (one of " + joined(allowed) + ")", text, "refusal.one_label", {{"labels", joined(allowed)}});
  return findLabel(t, allowed, text);
}

glm::dvec2 parseFloorPoint(const std::string& text) {
  const std::string t = trim(text);
  const auto comma = t.find(',');
  if (comma == std::string::npos || t.find(',', comma + 1) != std::string::npos)
    fail(kFloorPoint, text, "refusal.floor_point");
  return {parseReal(trim(t.substr(0, comma)), text), parseReal(trim(t.substr(comma + 1)), text)};
}

std::string parseLetter(const std::string& text) {
  const std::string t = upper(trim(text));
  for (const char letter : patternLetters())
    if (t == std::string(1, letter)) return t;
  fail("one of the letters C, K, R, X, Y", text, "refusal.letter");
}

glm::dvec3 parseDirection(const std::string& text) {
  const char* expected = "a direction 'x,y,z' (three numbers, not all 0)";
  std::string t = trim(text);
  std::replace(t.begin(), t.end(), ',', ' ');
  std::istringstream in(t);
  std::vector<std::string> parts;
  std::string part;
  while (in >> part) parts.push_back(part);
  const char* key = "refusal.direction";
  if (parts.size() != 3) fail(expected, text, key);
  glm::dvec3 d;
  for (int i = 0; i < 3; ++i) d[i] = parseNumber(parts[std::size_t(i)], text, expected, key);
  const double length = glm::length(d);
  if (!(length > 1e-12) || !std::isfinite(length)) fail(expected, text, key);
  return d / length;
}

GroundTruth parseAnswer(const Question& question, const std::string& text) { return answerForm(question).parse(question, text); }

}  // namespace tlab::tasks
