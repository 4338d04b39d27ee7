// The README's "Bring your own technique" blocks, run as written in a copy of examples/ (their
// `tlab` is build/bin/tlab, scripts/ the source tree's): a style file rendered, its --help, an
// experiment with it designed, simulated and analysed; a scene exported, drawn by VTK, and the
// pictures registered as a level, aligned and simulated.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>

#include "tests/support/run_command.hpp"

using namespace tlab::testing;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> readmeBlock(const std::string& name) {
  const std::string readme = readText(std::string(TLAB_SOURCE_DIR) + "/README.md");
  const auto marker = readme.find("<!-- " + name + ": tested -->");
  if (marker == std::string::npos) throw std::runtime_error("README.md: no " + name + " block");
  const auto begin = readme.find("```sh\n", marker), end = readme.find("```\n", begin + 6);
  std::istringstream block(readme.substr(begin + 6, end - begin - 6));
  std::vector<std::string> commands;
  for (std::string line; std::getline(block, line);)
    if (!line.empty()) commands.push_back(line);
  return commands;
}

// A folder holding a copy of examples/ (its style files and experiments), the commands' cwd.
fs::path workspace(const std::string& name) {
  const auto dir = freshDir(name);
  fs::copy(std::string(TLAB_SOURCE_DIR) + "/examples", dir / "examples", fs::copy_options::recursive);
  return dir;
}

CommandResult runAsWritten(const std::string& line, const fs::path& dir) {
  std::string command = std::regex_replace(line, std::regex("^tlab "), std::string(TLAB_EXE) + " ");
  command = std::regex_replace(command, std::regex(" scripts/"), " " + std::string(TLAB_SOURCE_DIR) + "/scripts/");
  return runCommand("cd " + quoted(dir.string()) + " && " + command);
}

}  // namespace

TEST(OwnTechniqueReadme, TheStyleFileCommandsWorkAsWritten) {
  const auto commands = readmeBlock("own-technique");
  ASSERT_EQ(commands.size(), 5u);
  const auto dir = workspace("readme_own_technique");
  for (const auto& c : commands) {
    const auto r = runAsWritten(c, dir);
    ASSERT_EQ(r.exitCode, 0) << c << ": " << r.err;
    if (c.find("--help") != std::string::npos) { EXPECT_NE(r.out.find("alpha_far=0.6  [0, 1]"), std::string::npos) << r.out; }
  }
  EXPECT_TRUE(fs::exists(dir / "mine.png"));
  EXPECT_TRUE(fs::exists(dir / "own.db"));
}

TEST(OwnTechniqueReadme, TheExternalImageCommandsWorkAsWritten) {
  const auto commands = readmeBlock("their-images");
  ASSERT_EQ(commands.size(), 7u);
  const auto dir = workspace("readme_their_images");
  for (const auto& c : commands) {
    const auto r = runAsWritten(c, dir);
    ASSERT_EQ(r.exitCode, 0) << c << ": " << r.out << r.err << " (scripts/setup.sh installs python3-vtk9 and xvfb)";
    if (c.find("tlab design") == 0) { EXPECT_NE(r.out.find("renders/torus.png: aligned with builtin:torus (IoU"), std::string::npos) << r.out; }
  }
}
