// tlab: the Transparency Lab command line. Parses, dispatches, and turns every error into one
// line on stderr with exit code 1.
#include <exception>
#include <iostream>

#include "app/commands.hpp"
#include "app/gl_option.hpp"

int main(int argc, char** argv) {
  CLI::App app{"tlab - Transparency Lab: illustrative transparency rendering and perceptual studies"};
  app.require_subcommand(1);
  app.fallthrough(false);
  tlab::app::addDemoCommand(app);
  tlab::app::addRenderCommand(app);
  tlab::app::addSceneCommand(app);
  tlab::app::addInspectCommand(app);
  tlab::app::addBenchCommand(app);
  tlab::app::addGalleryCommand(app);
  tlab::app::addFiguresCommand(app);
  tlab::app::addStatsCommand(app);
  tlab::app::addReproduceCommand(app);
  tlab::app::addStatcheckCommand(app);
  tlab::app::addReportCommand(app);
  tlab::app::addTimingCommand(app);
  tlab::app::addTaskCommand(app);
  tlab::app::addStimuliCommand(app);
  tlab::app::addDesignCommand(app);
  tlab::app::addRunCommand(app);
  tlab::app::addServeCommand(app);
  tlab::app::addLoadtestCommand(app);
  tlab::app::addSimulateCommand(app);
  tlab::app::addExportCommand(app);
  tlab::app::addAnalyzeCommand(app);
  tlab::app::addDropCommand(app);
  tlab::app::addVersionCommand(app);
  tlab::app::addGlOptions(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "tlab: error: " << e.what() << " (see --help)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "tlab: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
