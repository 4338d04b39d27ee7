#include <iostream>

#include "app/commands.hpp"

namespace tlab::app {

void addVersionCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("version", "Print the tlab version and git revision");
  cmd->callback([] { std::cout << "tlab " << TLAB_VERSION << " (" << TLAB_GIT_REVISION << ")\n"; });
}

}  // namespace tlab::app
