// tlab: the Transparency Lab command line. Parses, dispatches, and turns every error into one
// line on stderr with exit code 1.
#include <exception>
#include <iostream>
#include <string>

#include "app/commands.hpp"
#include "app/gl_option.hpp"

namespace {

// The deepest subcommand the command line chose ("tlab stats" for `tlab stats glmm`).
const CLI::App* chosen(const CLI::App& app) {
  const CLI::App* at = &app;
  for (auto subs = at->get_subcommands(); !subs.empty(); subs = at->get_subcommands()) at = subs.front();
  return at;
}

// When a command that needs a subcommand got a word that is none of them: the one line that
// names the word and lists the known ones (CLI11 alone says "A subcommand is required").
std::string unknownSubcommand(const CLI::App& app) {
  const CLI::App* at = chosen(app);
  const auto subcommands = at->get_subcommands([](const CLI::App* s) { return !s->get_name().empty(); });
  if (subcommands.empty()) return {};
  std::string word;
  for (const CLI::App* holder : {at, &app})
    for (const auto& r : holder->remaining())
      if (word.empty() && !r.empty() && r.front() != '-') word = r;
  std::string known;
  for (const CLI::App* s : subcommands)
    if (!s->get_group().empty()) known += (known.empty() ? "" : ", ") + s->get_name();
  std::string path;
  for (const CLI::App* p = at; p && p != &app; p = p->get_parent()) path = " " + p->get_name() + path;
  path = "tlab" + path;
  return (word.empty() ? "'" + path + "' needs a command" : "unknown command '" + word + "' for '" + path + "'") + " (known: " + known + ")";
}

// When a required argument is missing but the command line also held an option the command does
// not know: that option, as CLI11 names it when nothing is missing. CLI11 checks the required
// arguments first, so `tlab render --versoin` said "scene is required" and hid the typo.
std::string unexpectedOption(const CLI::App& app) {
  std::string options;
  for (const CLI::App* at = chosen(app); at; at = at->get_parent())
    for (const auto& r : at->remaining())
      if (r.size() > 1 && r.front() == '-') options += (options.empty() ? "" : " ") + r;
  return options.empty() ? "" : "The following argument was not expected: " + options;
}

}  // namespace

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
  tlab::app::addTextsCommand(app);
  tlab::app::addRunCommand(app);
  tlab::app::addServeCommand(app);
  tlab::app::addLoadtestCommand(app);
  tlab::app::addSimulateCommand(app);
  tlab::app::addExportCommand(app);
  tlab::app::addReplayCommand(app);
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
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    const bool required = dynamic_cast<const CLI::RequiredError*>(&e) != nullptr;
    std::string unknown = required ? unexpectedOption(app) : "";
    if (unknown.empty() && required) unknown = unknownSubcommand(app);
    std::cerr << "tlab: error: " << (unknown.empty() ? std::string(e.what()) : unknown) << " (see --help)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "tlab: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
