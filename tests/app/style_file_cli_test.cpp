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

// A declared default is used, recorded and listed with every digit it has: with one of seven
// significant digits at the end of its range, the style used to be refused by its own default
// ("0.123457 is outside [0, 0.123457]").
TEST(StyleFileCli, ADefaultOfSevenDigitsRendersAsDeclared) {
  const auto dir = freshDir("style_cli_digits");
  const auto file = (dir / "digits.glsl").string();
  std::string text = readText(kStyles + "constant.glsl");
  text.replace(text.find("default = 0.25"), 14, "default = 0.1234567");
  text.replace(text.find("range = [0.0, 1.0]"), 18, "range = [0.0, 0.1234567]");
  std::ofstream(file) << text;
  const std::string render = kTlab + " render builtin:torus --style " + file + " --size 40x30 -o ";
  const auto byDefault = runCommand(render + (dir / "default.png").string());
  ASSERT_EQ(byDefault.exitCode, 0) << byDefault.err;
  const auto given = runCommand(render + (dir / "given.png").string() + " --set alpha=0.1234567");
  ASSERT_EQ(given.exitCode, 0) << given.err;
  EXPECT_EQ(readText((dir / "default.png").string()), readText((dir / "given.png").string()));
  const auto help = runCommand(kTlab + " render --style " + file + " --help");
  EXPECT_NE(help.out.find("alpha=0.1234567  [0, 0.1234567]  opacity of every layer"), std::string::npos) << help.out;
}

// An int parameter whose range no GLSL int holds is refused where it is declared (--set
// alpha=3000000000 used to pass the range check and reach the shader as some other number).
TEST(StyleFileCli, AnIntRangeBeyondAGlslIntIsOneLineNamingTheFileAndLine) {
  const auto dir = freshDir("style_cli_int");
  const auto file = (dir / "wide.glsl").string();
  std::string text = readText(kStyles + "constant.glsl");
  text.replace(text.find("type = \"float\""), 14, "type = \"int\"");
  text.replace(text.find("default = 0.25"), 14, "default = 0");
  text.replace(text.find("range = [0.0, 1.0]"), 18, "range = [0, 1e12]");
  text.replace(text.find("T * alpha *"), 11, "T * float(alpha) *");
  std::ofstream(file) << text;
  int line = 1;
  for (std::size_t i = 0; i < text.find("range = [0, 1e12]"); ++i) line += text[i] == '\n';
  expectOneLineError(runCommand(kTlab + " render builtin:torus --style " + file + " --set alpha=3000000000 -o " +
                                (dir / "x.png").string()),
                     "tlab: error: " + file + ":" + std::to_string(line) + ": parameter[1].range: an int parameter's range lies within");
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}
