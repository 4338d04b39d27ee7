#pragma once
// What this binary is: the project version and the git revision it was built from, as every study
// record, report and replay stores it ("0.1.0+1fc72aa", "-dirty" appended where tracked files
// differed from that commit at build time). buildRevision() is generated at every build by
// cmake/RevisionScript.cmake, so a rebuild after a pull or an edit records the tree it was built from.
#include <string>
#include <string_view>

namespace tlab::app {

std::string_view buildRevision();

// TLAB_VERSION "+" buildRevision() (cmd_version.cpp, beside the line `tlab version` prints).
std::string versionString();

}  // namespace tlab::app
