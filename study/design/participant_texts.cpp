#include "study/design/participant_texts.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <toml++/toml.h>

namespace tlab::study {

// study/design/texts/<language>.toml, embedded at build time (study/CMakeLists.txt).
std::string_view participantTextFile(std::string_view name);

namespace {

const char* const kLanguages[] = {"de", "en", "fr"};

// Nested tables flattened to dotted keys: [count] trials.one = ... -> "count.trials.one".
void flatten(const toml::table& table, const std::string& prefix, std::map<std::string, std::string>& out) {
  for (auto&& [key, node] : table) {
    const std::string name = prefix + std::string(key.str());
    if (const toml::table* inner = node.as_table()) flatten(*inner, name + ".", out);
    else if (const auto* text = node.as_string()) out[name] = text->get();
    else throw std::logic_error("participant texts: " + name + " is not a string");
  }
}

// Whether n takes the singular form: French counts 0 and 1 as singular, English and German only 1.
bool singular(const std::string& language, double n) { return language == "fr" ? (n >= 0.0 && n < 2.0) : n == 1.0; }

}  // namespace

std::vector<std::string> shippedLanguages() { return {std::begin(kLanguages), std::end(kLanguages)}; }

std::map<std::string, std::string> shippedTexts(const std::string& language) {
  // The embedded files never change: read once (every experiment and form check asks for them).
  static const std::map<std::string, std::map<std::string, std::string>> shipped = [] {
    std::map<std::string, std::map<std::string, std::string>> tables;
    for (const char* l : kLanguages) {
      const std::string name = std::string(l) + ".toml";
      flatten(toml::parse(participantTextFile(name), name), "", tables[l]);
    }
    return tables;
  }();
  const auto it = shipped.find(language);
  return it == shipped.end() ? std::map<std::string, std::string>() : it->second;
}

std::set<std::string> placeholdersOf(const std::string& text) {
  std::set<std::string> out;
  for (std::size_t open = text.find('{'); open != std::string::npos; open = text.find('{', open + 1)) {
    std::size_t end = open + 1;
    while (end < text.size() && ((text[end] >= 'a' && text[end] <= 'z') || text[end] == '_')) ++end;
    if (end > open + 1 && end < text.size() && text[end] == '}') out.insert(text.substr(open + 1, end - open - 1));
  }
  return out;
}

std::set<std::string> ParticipantTexts::valuesOf(const std::string& key) {
  const auto english = shippedTexts("en");
  std::set<std::string> out;
  const auto dot = key.rfind('.');
  const std::string form = dot == std::string::npos ? "" : key.substr(dot);
  const std::string base = key.substr(0, dot);
  const bool plural = form == ".one" || form == ".other";
  for (const std::string& k : plural ? std::vector<std::string>{base + ".one", base + ".other"} : std::vector<std::string>{key}) {
    const auto it = english.find(k);
    if (it == english.end()) continue;
    const auto values = placeholdersOf(it->second);
    out.insert(values.begin(), values.end());
  }
  return out;
}

ParticipantTexts::ParticipantTexts() : ParticipantTexts("en") {}

ParticipantTexts::ParticipantTexts(const std::string& language) : language_(language), texts_(shippedTexts("en")) {
  const auto translation = shippedTexts(language);
  for (auto& [key, text] : texts_) {
    const auto it = translation.find(key);
    translated_[key] = language == "en" || it != translation.end();
    if (it != translation.end()) text = it->second;
  }
}

const std::string& ParticipantTexts::text(const std::string& key) const {
  const auto it = texts_.find(key);
  if (it == texts_.end()) throw std::out_of_range("text." + key + ": unknown key");
  return it->second;
}

std::string ParticipantTexts::format(const std::string& key, const std::map<std::string, std::string>& values) const {
  const std::string& pattern = text(key);
  std::string out;
  for (std::size_t i = 0; i < pattern.size();) {
    const std::size_t close = pattern[i] == '{' ? pattern.find('}', i) : std::string::npos;
    const auto value = close == std::string::npos ? values.end() : values.find(pattern.substr(i + 1, close - i - 1));
    if (value != values.end()) {
      out += value->second;
      i = close + 1;
    } else {
      out += pattern[i++];
    }
  }
  return out;
}

std::string ParticipantTexts::count(const std::string& key, long n, std::map<std::string, std::string> values) const {
  values["n"] = std::to_string(n);
  return format(key + (singular(language_, double(n)) ? ".one" : ".other"), values);
}

std::string ParticipantTexts::amount(const std::string& key, double value) const {
  return format(key + (singular(language_, value) ? ".one" : ".other"), {{"n", number(value)}});
}

std::string ParticipantTexts::number(double value) const {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  std::string out = text;
  if (language_ == "de" || language_ == "fr")
    for (char& c : out)
      if (c == '.') c = ',';
  return out;
}

void ParticipantTexts::set(const std::string& key, const std::string& value) {
  const auto it = texts_.find(key);
  if (it == texts_.end()) throw std::out_of_range("unknown key");
  it->second = value;
  translated_[key] = true;
  overrides_[key] = value;
}

ParticipantTexts ParticipantTexts::inLanguage(const std::string& language) const {
  ParticipantTexts out(language);
  for (const auto& [key, value] : overrides_) out.set(key, value);
  return out;
}

std::vector<std::string> ParticipantTexts::untranslated() const {
  std::vector<std::string> out;
  for (const auto& [key, done] : translated_)
    if (!done) out.push_back(key);
  return out;
}

}  // namespace tlab::study
