// End-to-end: `tlab render` and `tlab inspect` as a user runs them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"
#include "tests/support/tlab_version.hpp"

using namespace tlab::testing;
namespace fs = std::filesystem;

namespace {

const std::string kTlab = TLAB_EXE;

// Width and height from a PNG's IHDR chunk.
std::pair<int, int> pngSize(const std::string& path) {
  const std::string bytes = readText(path);
  if (bytes.size() < 24 || bytes.substr(1, 3) != "PNG") return {0, 0};
  const auto be32 = [&](std::size_t o) {
    return (int(std::uint8_t(bytes[o])) << 24) | (int(std::uint8_t(bytes[o + 1])) << 16) |
           (int(std::uint8_t(bytes[o + 2])) << 8) | int(std::uint8_t(bytes[o + 3]));
  };
  return {be32(16), be32(20)};
}

void expectOneLineError(const CommandResult& r, const std::string& needle) {
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
}

}  // namespace

TEST(RenderCli, WritesAPngOfTheRequestedSizeAndStats) {
  const auto dir = freshDir("render_cli");
  const auto png = (dir / "torus.png").string(), stats = (dir / "stats.json").string(), pgm = (dir / "c.pgm").string();
  const auto r = runCommand(kTlab + " render builtin:torus --style constant --set alpha=0.4 --size 120x90 -o " + png +
                            " --stats-json " + stats + " --layers-out " + pgm);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(pngSize(png), std::make_pair(120, 90));
  const auto j = nlohmann::json::parse(readText(stats));
  EXPECT_GT(j["fragments"].get<long>(), 0);
  EXPECT_EQ(j["camera"]["width"], 120);
  EXPECT_TRUE(j["pass_ms"].contains("fill"));
  // constant's compose pass sorts (issue #29), except where the host passes run (llvmpipe): there
  // the colours are sorted by host code (the twenty-eighth round)
  const bool onCpu = j["gpu"]["renderer"].get<std::string>().rfind("llvmpipe", 0) == 0;
  EXPECT_EQ(j["passes_run"], onCpu ? nlohmann::json::array({"fill", "sort", "compose"}) : nlohmann::json::array({"fill", "compose"}));
  const std::string version = tlabVersionString();
  ASSERT_NE(version, "");
  EXPECT_EQ(j["tlab_version"], version);
  EXPECT_EQ(readText(pgm).rfind("P5\n120 90\n65535\n", 0), 0u);
}

TEST(RenderCli, ExplicitCameraIsUsedAndReported) {
  const auto dir = freshDir("render_camera");
  const auto png = (dir / "a.png").string(), stats = (dir / "s.json").string();
  const auto r = runCommand(kTlab + " render builtin:sphere --style opaque --size 32x32 --camera 'eye=0,0,4 target=0,0,0 up=0,1,0 fovy=40' -o " +
                            png + " --stats-json " + stats);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(readText(stats));
  EXPECT_EQ(j["camera"]["eye"], nlohmann::json::array({0.0, 0.0, 4.0}));
  EXPECT_DOUBLE_EQ(j["camera"]["fovy"].get<double>(), 40.0);
}

TEST(RenderCli, SameBytesWithOneAndTwoRasterizerThreads) {
  const auto dir = freshDir("render_threads");
  const auto a = (dir / "a.png").string(), b = (dir / "b.png").string();
  const std::string args = " render builtin:open-cylinders --style constant --size 160x120 -o ";
  ASSERT_EQ(runCommand("LP_NUM_THREADS=1 " + kTlab + args + a).exitCode, 0);
  ASSERT_EQ(runCommand("LP_NUM_THREADS=2 " + kTlab + args + b).exitCode, 0);
  EXPECT_TRUE(readText(a) == readText(b)) << "images differ between 1 and 2 threads";
  EXPECT_FALSE(readText(a).empty());
}

TEST(RenderCli, InspectPrintsTheSortedList) {
  const auto r = runCommand(kTlab + " inspect builtin:nested-spheres?n=3 --size 65x65 --pixel 32,32 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["fragments"].size(), 6u);
  EXPECT_LT(j["fragments"][0]["depth"].get<double>(), j["fragments"][5]["depth"].get<double>());
}

TEST(RenderCli, BadInputGivesOneLineAndExitOne) {
  const auto dir = freshDir("render_errors");
  const auto out = (dir / "x.png").string();
  const auto notGltf = (dir / "notes.txt").string();
  std::ofstream(notGltf) << "not a scene";
  const auto empty = (dir / "empty.gltf").string();
  std::ofstream(empty) << R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"scene":0,"nodes":[{}]})";
  expectOneLineError(runCommand(kTlab + " render /no/such/file.gltf -o " + out), "no such file");
  expectOneLineError(runCommand(kTlab + " render " + notGltf + " -o " + out), "not a glTF file");
  expectOneLineError(runCommand(kTlab + " render " + empty + " -o " + out), "no triangles");
  expectOneLineError(runCommand(kTlab + " render builtin:sphere --style fancy -o " + out), "unknown style 'fancy'");
  expectOneLineError(runCommand(kTlab + " render builtin:sphere --set alpha=2 -o " + out), "outside [0, 1]");
  expectOneLineError(runCommand(kTlab + " render builtin:sphere --set nonsense -o " + out), "key=value");
  expectOneLineError(runCommand(kTlab + " render builtin:sphere --size 10by10 -o " + out), "--size");
  expectOneLineError(runCommand(kTlab + " render builtin:sphere --frobnicate -o " + out), "frobnicate");
  // A camera looking straight down with the default up drew NaNs (found by fuzz/render_options).
  expectOneLineError(runCommand(kTlab + " render builtin:sphere --camera 'eye=0,2.2,0' -o " + out),
                     "--camera field 'up': points along the line of sight");
  EXPECT_FALSE(fs::exists(out));  // nothing half-written
}

TEST(RenderCli, EverySubcommandHasHelp) {
  for (const std::string sub : {"render", "inspect"}) {
    const auto r = runCommand(kTlab + " " + sub + " --help");
    EXPECT_EQ(r.exitCode, 0) << sub;
    EXPECT_NE(r.out.find("--"), std::string::npos) << sub;
  }
}

TEST(RenderCli, DynamicStyleRendersTheAbstractWorldAndValidatesItsParameters) {
  const auto dir = freshDir("render_dynamic");
  const auto png = (dir / "a.png").string(), stats = (dir / "s.json").string();
  const auto r = runCommand(kTlab + " render 'builtin:abstract?seed=3' --style dynamic --set mask=ellipse --set max_layers=2 " +
                            "--size 96x72 -o " + png + " --stats-json " + stats);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(pngSize(png), std::make_pair(96, 72));
  EXPECT_EQ(nlohmann::json::parse(readText(stats))["passes_run"],
            nlohmann::json::array({"fill", "sort", "order", "mask", "compose"}));
  expectOneLineError(runCommand(kTlab + " render builtin:sphere --style dynamic --set border=2.5 -o " + png), "border must be a whole number");
  expectOneLineError(runCommand(kTlab + " render builtin:sphere --style dynamic --set mode=lens -o " + png), "mode");
}
