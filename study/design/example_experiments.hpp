#pragma once
// The example experiment files of examples/, embedded in tlab at build time (study/CMakeLists.txt),
// so `tlab demo` runs them from any directory and stores exactly the text it ran.
#include <string_view>

namespace tlab::study {

// The text of examples/<name> ("carnecky2013.toml", "elmqvist.toml"); throws for other names.
std::string_view exampleExperimentText(std::string_view name);

}  // namespace tlab::study
