// Every command line the README shows a newcomer — the main job's two demos, the researcher's
// guide, the tour and "Running a study: the commands" — runs here as written, with `tlab` on the
// PATH, in a folder where examples/ and tests/ are the repository's. Placeholders (FILE, DIR,
// data.csv, EXPERIMENT.toml, [optional] parts, "...") are mapped to real files the test makes;
// the map below says, for each command as written, what runs. A command the README gains or
// changes without a line here fails CommandsShownAreTheCommandsRun, so the README and its test
// change together. The online steps have their own test (ServeReadme.TheOnlineStepsWorkAsWritten).
// Each group is its own TEST so ctest runs them side by side.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_command.hpp"

namespace tlab::testing {
namespace {

namespace fs = std::filesystem;

// The README sections whose commands run here.
const std::vector<std::string> kSections = {"## What the main job does", "## A researcher's guide", "## A tour",
                                            "## Tasks with exact ground truth", "## Running a study: the commands"};

std::string section(const std::string& readme, const std::string& heading) {
  const auto begin = readme.find("\n" + heading);
  if (begin == std::string::npos) throw std::runtime_error("README.md: no section '" + heading + "'");
  const auto end = readme.find("\n## ", begin + 1);
  return readme.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(' ');
  return b == std::string::npos ? "" : s.substr(b, s.find_last_not_of(' ') - b + 1);
}

// The `tlab ...` command lines of a section: lines of its ```sh blocks (without a trailing
// comment) and inline code spans.
std::vector<std::string> commandsIn(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream lines(text);
  bool block = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("```", 0) == 0) {
      block = !block;
      continue;
    }
    if (block) {
      if (line.rfind("tlab ", 0) == 0) out.push_back(trimmed(line.substr(0, line.find("  #"))));
      continue;
    }
    static const std::regex span("`(tlab [^`]*)`");
    for (std::sregex_iterator m(line.begin(), line.end(), span), end; m != end; ++m) out.push_back((*m)[1]);
  }
  return out;
}

std::vector<std::string> readmeCommands() {
  const std::string readme = readText(std::string(TLAB_SOURCE_DIR) + "/README.md");
  std::vector<std::string> all;
  for (const auto& heading : kSections)
    for (auto& c : commandsIn(section(readme, heading))) all.push_back(std::move(c));
  return all;
}

// What runs for each command as written: "" runs it exactly as written; "=OTHER" is run by
// OTHER's line (the same command, shown twice or in short); anything else is the command with
// its placeholders mapped. `group` is the TEST that runs it.
struct Mapping {
  std::string group;
  std::string run;
};

const std::map<std::string, Mapping>& mappings() {
  static const std::map<std::string, Mapping> m = {
      // The main job.
      {"tlab demo", {"demos", "=tlab demo --out out/demo"}},
      {"tlab demo --out out/demo", {"demos", ""}},
      {"tlab demo --elmqvist --out out/elmqvist", {"demos", ""}},
      // The researcher's guide.
      {"tlab design FILE", {"guide", "tlab design study.toml"}},
      {"tlab simulate FILE --participants 24 --db pilot.db", {"guide", "tlab simulate study.toml --participants 24 --db pilot.db"}},
      {"tlab simulate --help", {"guide", ""}},
      {"tlab simulate FILE --calibrate carnecky", {"guide", "tlab simulate study.toml --calibrate carnecky --participants 3"}},
      {"tlab simulate examples/carnecky2013.toml --calibrate carnecky",
       {"guide", "tlab simulate examples/carnecky2013.toml --calibrate carnecky --participants 3 --size 240x240"}},
      {"tlab run FILE --participant P07 --db study.db [--fullscreen]",
       {"guide", "xvfb-run -a -s '-screen 0 1280x1024x24' tlab run study.toml --participant P07 --db study.db --fullscreen --autopilot"}},
      {"tlab run --autopilot", {"guide", "=tlab run FILE --participant P07 --db study.db [--fullscreen]"}},
      {"tlab timing study.db", {"guide", ""}},
      {"tlab export study.db --csv DIR", {"guide", "tlab export study.db --csv csv"}},
      {"tlab analyze study.db", {"guide", ""}},
      {"tlab report study.db -o report.html", {"guide", ""}},
      {"tlab stats", {"guide", "=tlab stats ..."}},
      {"tlab stats ...", {"guide", "tlab stats friedman csv/trials.csv --dv correct --within method --subject participant --where phase=test"}},
      {"tlab stats anova csv/trials.csv --dv rt_seconds --within method --subject participant --where phase=test", {"guide", ""}},
      {"tlab reproduce carnecky", {"guide", ""}},
      {"tlab reproduce elmqvist", {"guide", ""}},
      {"tlab reproduce --table FILE.csv", {"guide", "tlab reproduce --table tests/data/analysis/carnecky_table1.csv"}},
      {"tlab statcheck FILE|DIR", {"guide", "tlab statcheck tests/data/analysis/statcheck_sample.html"}},
      // The tour.
      {"tlab render builtin:open-cylinders --style smart -o smart.png", {"tour", ""}},
      {"tlab render builtin:pretzel --style smart --set halos=off --size 1024x1024 -o p.png --stats-json s.json", {"tour", ""}},
      {"tlab inspect builtin:nested-spheres?n=3 --pixel 256,256", {"tour", ""}},
      {"tlab gallery --out out/gallery", {"tour", ""}},
      {"tlab figures --out out/figures", {"tour", "tlab figures --out out/figures --size 96x96"}},
      {"tlab task probe builtin:open-cylinders --task layer-index --count 5 --seed 1 --json", {"tour", ""}},
      {"tlab stimuli examples/stimulus-sets/carnecky-flow-surfaces.toml -o out/stimuli --jobs 2", {"tour", ""}},
      {"tlab stats anova data.csv --dv score --within method --subject participant --json", {"tour", ""}},
      // Tasks with exact ground truth: the shape tasks.
      {"tlab task probe 'builtin:nested-spheres?n=3' --task gauge-figure --count 3 --json", {"tasks", ""}},
      {"tlab simulate examples/shape-depiction.toml --participants 8 --db shape.db", {"tasks", ""}},
      {"tlab analyze shape.db", {"tasks", ""}},
      {"tlab task probe|check|list", {"tasks", "tlab task list"}},
      {"tlab task check --json", {"tasks", "tlab task check 'builtin:nested-spheres?n=3' --task gauge-figure --question 1 --answer 0,0,1 --json"}},
      // Running a study: the commands.
      {"tlab design examples/carnecky2013.toml", {"study", ""}},
      {"tlab run EXPERIMENT.toml --participant P01 --db study.db [--fullscreen] [--resume]",
       {"study", "xvfb-run -a -s '-screen 0 1280x1024x24' tlab run study.toml --participant P01 --db study.db --autopilot"}},
      {"tlab simulate EXPERIMENT.toml --participants 36 --db sim.db [--replicate R]",
       {"study", "tlab simulate study.toml --participants 36 --db sim.db"}},
      {"tlab simulate --first K", {"study", "tlab simulate study.toml --participants 2 --first 37 --db sim.db"}},
      {"tlab drop study.db --participant P03 --reason \"left early\"", {"study", "tlab drop sim.db --participant sim-003 --reason \"left early\""}},
      {"tlab export study.db --csv out/csv", {"study", "tlab export sim.db --csv out/csv"}},
      {"tlab version", {"study", ""}},
      {"tlab --version", {"study", ""}},
  };
  return m;
}

// The study file standing for FILE and EXPERIMENT.toml: the shipped Carnecky example at 240x240 (the demo's reduced size).
void writeStudyFile(const fs::path& dir) {
  std::string text = readText(std::string(TLAB_SOURCE_DIR) + "/examples/carnecky2013.toml");
  text = std::regex_replace(text, std::regex("size = \"800x800\""), "size = \"240x240\"");
  std::ofstream(dir / "study.toml") << text;
}

// A folder where the README's relative paths work: examples/ and tests/ of the repository.
fs::path workFolder(const std::string& name) {
  const fs::path dir = freshDir("readme_" + name);
  fs::create_directory_symlink(fs::path(TLAB_SOURCE_DIR) / "examples", dir / "examples");
  fs::create_directory_symlink(fs::path(TLAB_SOURCE_DIR) / "tests", dir / "tests");
  writeStudyFile(dir);
  return dir;
}

// Runs one README command (as mapped) in `dir` with tlab on the PATH.
CommandResult runInFolder(const fs::path& dir, const std::string& command) {
  const std::string path = fs::path(TLAB_EXE).parent_path().string();
  return runCommand("cd " + quoted(dir.string()) + " && PATH=" + quoted(path) + ":\"$PATH\" " + command);
}

std::string toRun(const std::string& written) {
  const Mapping& m = mappings().at(written);
  return m.run.empty() ? written : m.run;
}

// Runs every README command of `group` in the order the README shows them (with `before` run
// first: the files a placeholder stands for), and checks each exits 0.
void runGroup(const std::string& group, const fs::path& dir, const std::vector<std::string>& before = {}) {
  for (const auto& command : before) {
    const CommandResult r = runInFolder(dir, command);
    ASSERT_EQ(r.exitCode, 0) << command << "\n" << r.out << r.err;
  }
  std::set<std::string> ran;
  for (const auto& written : readmeCommands()) {
    const auto found = mappings().find(written);
    if (found == mappings().end() || found->second.group != group || !ran.insert(written).second) continue;
    const std::string command = toRun(written);
    if (command.rfind("=", 0) == 0) continue;  // run by the line it names
    SCOPED_TRACE(written);
    const CommandResult r = runInFolder(dir, command);
    EXPECT_EQ(r.exitCode, 0) << command << "\nstdout:\n" << r.out.substr(0, 4000) << "\nstderr:\n" << r.err;
  }
}

TEST(Readme, CommandsShownAreTheCommandsRun) {
  const auto commands = readmeCommands();
  ASSERT_GT(commands.size(), 30u);
  std::set<std::string> shown(commands.begin(), commands.end());
  for (const auto& c : shown) EXPECT_TRUE(mappings().count(c)) << "a README command no test runs: add it to mappings(): " << c;
  for (const auto& [written, m] : mappings()) {
    EXPECT_TRUE(shown.count(written)) << "the README no longer shows this command: " << written;
    if (m.run.rfind("=", 0) == 0) { EXPECT_TRUE(mappings().count(m.run.substr(1))) << written << " refers to " << m.run; }
  }
}

TEST(Readme, TheDemosRunAsWritten) {
  const fs::path dir = workFolder("demos");
  runGroup("demos", dir);
  for (const char* out : {"out/demo", "out/elmqvist"}) {
    EXPECT_TRUE(fs::exists(dir / out / "report.html")) << out;
    EXPECT_TRUE(fs::exists(dir / out / "study.db")) << out;
  }
}

TEST(Readme, TheResearchersGuideRunsAsWritten) {
  // study.db: two simulated participants first, then the guide's window session (P07) joins them,
  // so the export's tables have the subjects a within-subject test needs.
  runGroup("guide", workFolder("guide"), {"tlab simulate study.toml --participants 2 --db study.db"});
}

TEST(Readme, TheTourRunsAsWritten) {
  const fs::path dir = workFolder("tour");
  // data.csv: a long-format table with score, method and participant columns, from a small simulated study.
  runGroup("tour", dir,
           {"tlab simulate study.toml --participants 3 --db tour.db", "tlab export tour.db --csv tour-csv",
            "cp tour-csv/trials.csv data.csv"});
}

TEST(Readme, TheShapeTaskCommandsRunAsWritten) { runGroup("tasks", workFolder("tasks")); }

TEST(Readme, TheStudyCommandsRunAsWritten) {
  const fs::path dir = workFolder("study");
  runGroup("study", dir);
  // study.db is the window session's; the commands after drop read it as the README shows.
  for (const char* command : {"tlab timing study.db", "tlab analyze study.db", "tlab report study.db -o report.html"}) {
    const CommandResult r = runInFolder(dir, command);
    EXPECT_EQ(r.exitCode, 0) << command << "\n" << r.out << r.err;
  }
}

}  // namespace
}  // namespace tlab::testing
