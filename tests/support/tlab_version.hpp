#pragma once
// The version string the built tlab records in databases, manifests and JSON ("0.1.0+1fc72aa"),
// read from what `tlab version` prints ("tlab 0.1.0 (1fc72aa)"); empty when that is malformed.
#include <regex>
#include <string>

#include "tests/support/run_command.hpp"

namespace tlab::testing {

inline std::string tlabVersionString() {
  const std::string printed = runCommand(std::string(TLAB_EXE) + " version").out;
  std::smatch m;
  if (!std::regex_match(printed, m, std::regex("tlab ([0-9.]+) \\(([0-9a-f]+(-dirty)?|unknown)\\)\n"))) return "";
  return m[1].str() + "+" + m[2].str();
}

}  // namespace tlab::testing
