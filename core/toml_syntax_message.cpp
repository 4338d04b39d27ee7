#include "core/toml_syntax_message.hpp"

#include <optional>

namespace tlab::core {

namespace {

enum class Lexeme { Plain, Comment, Basic, Literal, MultiBasic, MultiLiteral };

bool startsWith(std::string_view text, std::size_t at, std::string_view what) { return text.substr(at, what.size()) == what; }

// The line of the opening quote of the first string in `text` that is never closed (a one-line
// string ends at its line break, a multi-line one at the end of the text), if there is one.
std::optional<unsigned> unterminatedStringLine(std::string_view text) {
  Lexeme state = Lexeme::Plain;
  unsigned line = 1, opened = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    switch (state) {
      case Lexeme::Plain:
        if (c == '#') state = Lexeme::Comment;
        else if (startsWith(text, i, "\"\"\"")) state = Lexeme::MultiBasic, opened = line, i += 2;
        else if (startsWith(text, i, "'''")) state = Lexeme::MultiLiteral, opened = line, i += 2;
        else if (c == '"') state = Lexeme::Basic, opened = line;
        else if (c == '\'') state = Lexeme::Literal, opened = line;
        break;
      case Lexeme::Comment:
        if (c == '\n') state = Lexeme::Plain;
        break;
      case Lexeme::Basic:
        if (c == '\\') ++i;
        else if (c == '"') state = Lexeme::Plain;
        else if (c == '\n') return opened;
        break;
      case Lexeme::Literal:
        if (c == '\'') state = Lexeme::Plain;
        else if (c == '\n') return opened;
        break;
      case Lexeme::MultiBasic:
        if (c == '\\') ++i;
        else if (startsWith(text, i, "\"\"\"")) state = Lexeme::Plain, i += 2;
        break;
      case Lexeme::MultiLiteral:
        if (startsWith(text, i, "'''")) state = Lexeme::Plain, i += 2;
        break;
    }
    if (c == '\n') ++line;
  }
  if (state == Lexeme::Plain || state == Lexeme::Comment) return std::nullopt;
  return opened;
}

}  // namespace

std::string tomlSyntaxMessage(std::string_view text, unsigned line, std::string_view description) {
  const bool aboutString = description.find("string") != std::string_view::npos;
  if (const auto opened = aboutString ? unterminatedStringLine(text) : std::nullopt)
    if (*opened <= line) return std::to_string(*opened) + ": unterminated string starting at line " + std::to_string(*opened) + " (a closing quote is missing)";
  return std::to_string(line) + ": " + std::string(description);
}

}  // namespace tlab::core
