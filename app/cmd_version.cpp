#include <iostream>

#include "app/build_revision.hpp"
#include "app/commands.hpp"

namespace tlab::app {

std::string versionString() { return std::string(TLAB_VERSION) + "+" + std::string(buildRevision()); }

void addVersionCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("version", "Print the tlab version and the git revision it was built from");
  cmd->callback([] { std::cout << "tlab " << TLAB_VERSION << " (" << buildRevision() << ")\n"; });
}

}  // namespace tlab::app
