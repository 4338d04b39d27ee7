// End-to-end: `tlab render --style FILE` as a researcher runs it with her own style file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"

using namespace tlab::testing;

namespace {

const std::string kTlab = TLAB_EXE;
const std::string kStyles = std::string(TLAB_SOURCE_DIR) + "/examples/styles/";

void expectOneLineError(const CommandResult& r, const std::string& start) {
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(start), std::string::npos) << r.err;
}

}  // namespace

TEST(StyleFileCli, RendersAStyleFileAndRecordsItsSha256) {
  const auto dir = freshDir("style_cli");
  const auto png = (dir / "d.png").string(), stats = (dir / "s.json").string();
  const auto file = kStyles + "depth_tinted_alpha.glsl";
  const auto r = runCommand(kTlab + " render builtin:torus --style " + file + " --set alpha_far=0.8 --size 80x60 -o " + png +
                            " --stats-json " + stats);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(png));
  const auto j = nlohmann::json::parse(readText(stats));
  EXPECT_EQ(j["style"], file);
  const auto sum = runCommand("sha256sum " + quoted(file));  // the coreutils tool, not tlab's own SHA-256
  ASSERT_EQ(sum.exitCode, 0);
  EXPECT_EQ(j["style_sha256"], sum.out.substr(0, 64));
  EXPECT_EQ(j["settings"]["alpha_far"], "0.8");
}

TEST(StyleFileCli, ParametersAreRangeCheckedAndListedByHelp) {
  const auto file = kStyles + "depth_tinted_alpha.glsl";
  expectOneLineError(runCommand(kTlab + " render builtin:torus --style " + file + " --set alpha_far=1.5 -o /dev/null"),
                     "style 'depth-tinted-alpha' parameter 'alpha_far' = 1.5 is outside [0, 1]");
  expectOneLineError(runCommand(kTlab + " render builtin:torus --style " + file + " --set alpha=0.5 -o /dev/null"),
                     "has no parameter 'alpha'");
  const auto help = runCommand(kTlab + " render --style " + file + " --help");
  EXPECT_EQ(help.exitCode, 0) << help.err;
  EXPECT_NE(help.out.find("depth-tinted-alpha"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("alpha_near=0.1  [0, 1]  opacity of a layer at the front of the scene"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("lighting=headlight"), std::string::npos) << help.out;
}

TEST(StyleFileCli, ABrokenStyleIsOneLineNamingTheFileAndLine) {
  const auto dir = freshDir("style_cli_broken");
  const auto file = (dir / "mine.glsl").string();
  std::string text = readText(kStyles + "constant.glsl");
  text.replace(text.find("T * alpha *"), 11, "T * alhpa *");
  std::ofstream(file) << text;
  int line = 1;
  for (std::size_t i = 0; i < text.find("alhpa"); ++i) line += text[i] == '\n';
  expectOneLineError(runCommand(kTlab + " render builtin:torus --style " + file + " -o " + (dir / "x.png").string()),
                     "tlab: error: " + file + ":" + std::to_string(line) + ": ");
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}
