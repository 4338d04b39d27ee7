#pragma once
// Reads a whole file into a string, bytes unchanged; nullopt when it cannot be opened (callers
// say which file and what it was for).
#include <optional>
#include <string>

namespace tlab::core {

std::optional<std::string> readFileText(const std::string& path);

}  // namespace tlab::core
