#pragma once
// The neutral code printed on a booklet page instead of the stimulus id (which names the scene,
// the style and the view: the condition, in a study the seed calls double blind). The manifest
// maps each code back to its stimulus ("booklet_code").
#include <algorithm>
#include <cctype>
#include <string>

namespace tlab::stimuli {

// The first 8 hex digits of the stimulus image's SHA-256, upper case: unique within a set.
inline std::string bookletCode(const std::string& sha256) {
  std::string code = sha256.substr(0, 8);
  std::transform(code.begin(), code.end(), code.begin(), [](unsigned char c) { return char(std::toupper(c)); });
  return code;
}

}  // namespace tlab::stimuli
