#pragma once
// The one-line message of a TOML syntax error. toml++ reports a string left open as "unescaped
// control characters other than TAB ..." (at the line break that ends a one-line string) or
// "encountered end-of-file" (a multi-line string never closed); a person needs to know where the
// string began. Pure text scanning: no TOML library below this floor.
#include <string>
#include <string_view>

namespace tlab::core {

// "LINE: message" for the parser's error at `line` with its `description`: when the text holds a
// string that is never closed, "unterminated string starting at line N" with N the line of its
// opening quote; otherwise the parser's own line and description.
std::string tomlSyntaxMessage(std::string_view text, unsigned line, std::string_view description);

}  // namespace tlab::core
