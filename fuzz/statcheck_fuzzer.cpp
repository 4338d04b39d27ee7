// Fuzz target: free text → statcheck report (APA scanner, p recomputation, verdicts). Any text
// is valid input, so nothing may throw.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "analysis/statcheck.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  tlab::analysis::statcheck(text, "fuzz.txt");
  return 0;
}
