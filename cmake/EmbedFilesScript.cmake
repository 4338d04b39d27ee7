# Script mode: writes OUT, a C++ file defining NAMESPACE::FUNCTION(name) -> the text of the file
# called `name` (raw string literals), for every file of FILES below BASE.
set(body "// Generated from files of the source tree by cmake/EmbedFilesScript.cmake. Do not edit.\n#include <string_view>\n#include <stdexcept>\n#include <string>\nnamespace ${NAMESPACE} {\nstd::string_view ${FUNCTION}(std::string_view name) {\n")
foreach(f IN LISTS FILES)
  file(READ ${BASE}/${f} text)
  string(APPEND body "  if (name == \"${f}\") return R\"tlabtext(${text})tlabtext\";\n")
endforeach()
string(APPEND body "  throw std::runtime_error(\"no embedded file named '\" + std::string(name) + \"'\");\n}\n}  // namespace ${NAMESPACE}\n")
file(WRITE ${OUT}.tmp "${body}")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
