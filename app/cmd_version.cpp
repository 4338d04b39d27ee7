#include <iostream>

#include "app/build_revision.hpp"
#include "app/commands.hpp"

namespace tlab::app {

std::string versionString() { return std::string(TLAB_VERSION) + "+" + std::string(buildRevision()); }

namespace {
std::string versionLine() { return "tlab " + std::string(TLAB_VERSION) + " (" + std::string(buildRevision()) + ")"; }
}  // namespace

// `tlab version`, and `tlab --version` as a newcomer types it: the same line.
void addVersionCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("version", "Print the tlab version and the git revision it was built from");
  cmd->callback([] { std::cout << versionLine() << "\n"; });
  app.set_version_flag("--version", versionLine, "Print the tlab version and the git revision it was built from");
}

}  // namespace tlab::app
