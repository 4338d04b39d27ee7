#include "core/file_text.hpp"

#include <fstream>
#include <sstream>

namespace tlab::core {

std::optional<std::string> readFileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace tlab::core
