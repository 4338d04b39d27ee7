# Script mode: writes OUT, a C++ file mapping shader names to their text (raw string literals).
set(body "// Generated from the .glsl files next to the passes that own them. Do not edit.\n#include <string_view>\n#include <stdexcept>\n#include <string>\nnamespace tlab::gpu {\nstd::string_view embeddedShader(std::string_view name) {\n")
foreach(f IN LISTS FILES)
  file(READ ${BASE}/${f} text)
  string(APPEND body "  if (name == \"${f}\") return R\"tlabglsl(${text})tlabglsl\";\n")
endforeach()
string(APPEND body "  throw std::runtime_error(\"no embedded shader named '\" + std::string(name) + \"'\");\n}\n}  // namespace tlab::gpu\n")
file(WRITE ${OUT}.tmp "${body}")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
