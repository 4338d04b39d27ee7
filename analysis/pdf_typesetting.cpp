// statcheck's corrections of PDF typesetting (document_text.hpp); the text itself comes from
// poppler in the document-reader module (document_module.cpp).
#include <cctype>
#include <memory>

#include "analysis/analysis_error.hpp"
#include "analysis/document_text.hpp"

namespace tlab::analysis {

namespace {

bool isLetter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// statcheck's lookahead (?=\s?-?\s?\.?\d) at position i.
bool numberFollows(std::string_view s, std::size_t i) {
  const auto skip = [&](auto pred) {
    if (i < s.size() && pred(s[i])) ++i;
  };
  skip(isSpace);
  skip([](char c) { return c == '-'; });
  skip(isSpace);
  skip([](char c) { return c == '.'; });
  return i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])) != 0;
}

std::string replaceCodePoints(std::string_view in) {
  struct Replacement {
    std::string_view from, to;
  };
  static constexpr Replacement replacements[] = {
      {"\xE2\xAB\xBD", "="},         // U+2AFD double solidus (APA journals)
      {"\xC2\xBC", "="},             // U+00BC ¼ (Elsevier)
      {"\xE2\xAC\x8D", "<"},         // U+2B0D (APA journals)
      {"!", "<"},                    // (Journal of Consumer Research)
      {"\xE2\xAB\xBA", "-"},         // U+2AFA (APA journals)
      {"\xE2\x90\xB9", "\xCF\x87"},  // U+2439 → χ (APA journals)
  };
  std::string out;
  for (std::size_t i = 0; i < in.size();) {
    bool replaced = false;
    for (const auto& r : replacements)
      if (in.substr(i, r.from.size()) == r.from) {
        out += r.to;
        i += r.from.size();
        replaced = true;
        break;
      }
    if (!replaced) out.push_back(in[i++]);
  }
  return out;
}

}  // namespace

std::string fixPdfTypesetting(std::string_view text) {
  std::string s = replaceCodePoints(text);
  for (std::size_t i = 0; i < s.size(); ++i) {
    // Only a letter standing alone (not inside a word) is taken for a symbol; statcheck takes
    // any, which turns "lab 1" into "la< 1" (README: deliberate differences).
    const char before = i > 0 ? s[i - 1] : ' ';
    if (isLetter(before)) continue;
    const char c = s[i];
    const bool afterComparison = before == '=' || before == '<' || before == '>';
    if ((c == 'b' || c == 'N') && !afterComparison && numberFollows(s, i + 1)) {
      s[i] = c == 'b' ? '<' : '>';
    } else if (c == 'p' && numberFollows(s, i + 1)) {
      const bool afterComma = before == ',' || (i >= 2 && isSpace(before) && s[i - 2] == ',');
      if (!afterComma) s[i] = '=';
    } else if (c == 'B' && i + 1 < s.size() && std::string_view("tFrQzZ").find(s[i + 1]) != std::string_view::npos) {
      s[i] = '"';
    }
  }
  return s;
}

}  // namespace tlab::analysis
