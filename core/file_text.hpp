#pragma once
// Reads a whole file into a string, bytes unchanged; nullopt when it cannot be opened (callers
// say which file and what it was for). The last non-empty line of a text: what a program's log
// says last (why it failed).
#include <optional>
#include <string>

namespace tlab::core {

std::optional<std::string> readFileText(const std::string& path);

// The last line of `text` that holds more than blanks; "" when none does.
std::string lastNonEmptyLine(const std::string& text);

}  // namespace tlab::core
