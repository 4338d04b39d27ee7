// End to end: `tlab bench render --scene` and `tlab bench all` print the table a lab runs on its
// GPU (structure only: speed is never asserted).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"
#include "tests/support/tlab_version.hpp"

using namespace tlab::testing;

namespace {
const std::string kTlab = TLAB_EXE;
}  // namespace

TEST(BenchCli, OneSceneInSeveralStylesWithTheGlAndWhatRan) {
  const auto r = runCommand(kTlab + " bench render --scene builtin:nested-spheres?n=2 --style constant,smart --size 32x24 "
                                    "--frames 2 --gl osmesa --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["gl"]["backend"], "osmesa");
  EXPECT_NE(j["gl"]["renderer"].get<std::string>(), "");
  const std::string version = tlabVersionString();
  ASSERT_NE(version, "");
  EXPECT_EQ(j["tlab_version"], version);  // which build measured it
  ASSERT_EQ(j["rows"].size(), 2u);
  const auto& constant = j["rows"][0];
  const auto& smart = j["rows"][1];
  EXPECT_EQ(constant["style"], "constant");
  EXPECT_EQ(constant["ratio_to_reference"], 1.0);
  EXPECT_EQ(constant["size"], "32x24");
  EXPECT_GT(constant["fragments"].get<double>(), 0);
  EXPECT_EQ(smart["fragments"], constant["fragments"]);
  EXPECT_GT(smart["frame_ms"].get<double>(), 0);
  EXPECT_TRUE(smart["pass_ms"].contains("connect")) << smart;
  EXPECT_FALSE(smart["operations"].empty()) << smart;
}

TEST(BenchCli, AllStylesOnTheGivenScenes) {
  const auto r = runCommand(kTlab + " bench all --scenes builtin:sphere --sizes 16x16 --frames 1 --comparisons dynamic --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto styles = runCommand(kTlab + " render --help").out;
  ASSERT_GE(j["rows"].size(), 8u);
  EXPECT_EQ(j["rows"][0]["style"], "constant");
  for (const auto& row : j["rows"]) {
    EXPECT_EQ(row["scene"], "builtin:sphere");
    EXPECT_NE(styles.find("  " + row["style"].get<std::string>() + ":"), std::string::npos) << row;
    EXPECT_FALSE(row.contains("error")) << row;
  }
  // The seed's comparison ran with the same GL: Elmqvist's dynamic against opaque.
  ASSERT_TRUE(j["comparisons"].contains("dynamic")) << j["comparisons"];
  EXPECT_GT(j["comparisons"]["dynamic"]["ratio"].get<double>(), 0);
  EXPECT_FALSE(j["comparisons"].contains("peel"));
}

TEST(BenchCli, SceneOptionsWithoutASceneAndUnknownStylesAreOneLine) {
  for (const auto& [args, part] : {std::pair{"bench render --quick --size 64x64", "--size needs --scene"},
                                   std::pair{"bench render --scene builtin:sphere --style constant,glass", "unknown style 'glass'"},
                                   std::pair{"bench render --scene builtin:sphere --size 12", "--size"},
                                   std::pair{"bench all --scenes builtin:sphere --sizes 8x8 --frames 1 --comparisons peel,fast",
                                             "'fast' is not buckets, dynamic or peel"}}) {
    const auto r = runCommand(kTlab + " " + args);
    EXPECT_EQ(r.exitCode, 1) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
  }
}

// --until PASS ends every frame after that pass (bench/count_instructions.sh counts a pass's work
// as the difference between two such runs): the passes after it neither run nor are timed, the
// table lists the ones that ran in their order, and a pass the frame does not have is one line.
TEST(BenchCli, UntilEndsEachFrameAfterThePassNamed) {
  const std::string base = kTlab + " bench render --scene builtin:nested-spheres?n=2 --size 32x24 --frames 1 --gl osmesa ";
  for (const auto& [until, expected] : {std::pair{"fill", std::vector<std::string>{"fill"}},
                                        std::pair{"sort", std::vector<std::string>{"fill", "sort"}},
                                        std::pair{"connect", std::vector<std::string>{"fill", "sort", "connect"}},
                                        std::pair{"compose", std::vector<std::string>{"fill", "sort", "connect", "solve", "compose"}}}) {
    const auto r = runCommand(base + "--style smart --until " + until);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string listed;  // the last column of the row: "fill 1.2, sort 0.3"
    for (const auto& name : expected) listed += (listed.empty() ? "" : " [0-9.]+, ") + name;
    EXPECT_TRUE(std::regex_search(r.out, std::regex("  " + listed + " [0-9.]+\n$"))) << until << "\n" << r.out;
  }
  const auto j = nlohmann::json::parse(runCommand(base + "--style smart --until connect --json").out);
  const auto& row = j["rows"][0];
  EXPECT_EQ(row["pass_ms"].size(), 3u) << row;
  EXPECT_FALSE(row["pass_ms"].contains("solve")) << row;
  EXPECT_GT(row["fragments"].get<double>(), 0);

  for (const auto& [args, part] :
       {std::pair{"--style constant,smart --until connect", "--until: constant's frame has no pass 'connect' (its passes: fill, sort, compose)"},
        std::pair{"--style smart --until blend", "--until: smart's frame has no pass 'blend' (its passes: fill, sort, connect, solve, compose)"}}) {
    const auto r = runCommand(base + args);
    EXPECT_EQ(r.exitCode, 1) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
  }
  const auto r = runCommand(kTlab + " bench render --until fill");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("--until needs --scene"), std::string::npos) << r.err;
}

// --parts times each pass's parts as well (the connect pass's phases, the solve's steps, the fill's
// rasterization and prefix sum, the compose's read-back): by name and count under each row, and in
// the JSON; a frame's parts lie within their passes (one frame: medians of one sample). The solve's
// frontier steps are one part as host code (llvmpipe's default), one a step as the shader; the
// connect pass's phase 2 is one part either way, named for where it ran.
TEST(BenchCli, PartsListEachPassPiecesUnderItsRow) {
  const std::string base =
      kTlab + " bench render --scene builtin:nested-spheres?n=2 --size 48x40 --gl osmesa --style constant,smart ";
  const auto r = runCommand(base + "--frames 1 --parts --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["rows"].size(), 2u);
  for (const auto& row : j["rows"]) {
    ASSERT_TRUE(row.contains("part_ms")) << row;
    EXPECT_EQ(row["part_ms"].size(), row["part_counts"].size()) << row;
    // (both styles' colours blended by host code on llvmpipe, straight into the image: issue #29)
    EXPECT_TRUE(row["part_ms"].contains("compose blend on the host")) << row;
    EXPECT_FALSE(row["part_ms"].contains("compose read-back")) << row;
    for (const auto& [pass, ms] : row["pass_ms"].items()) {
      double inside = 0;
      for (const auto& [part, partMs] : row["part_ms"].items())
        if (part.rfind(pass + " ", 0) == 0) inside += partMs.get<double>();
      EXPECT_LE(inside, ms.get<double>() + 1e-9) << pass << "\n" << row;
    }
  }
  const auto& smart = j["rows"][1];
  // llvmpipe runs the connect pass's phases 1 and 2 and the solve's frontier steps as host code: one part each.
  for (const char* name : {"connect phase 1 on the host", "connect phase 2 on the host", "solve beta frontier on the host"})
    EXPECT_TRUE(smart["part_ms"].contains(name)) << name << "\n" << smart;
  EXPECT_EQ(smart["part_counts"]["connect phase 1 on the host"], 1);
  EXPECT_EQ(smart["part_counts"]["solve beta frontier on the host"], 1);
  const std::string beta = smart["operations"][1].get<std::string>();  // "solve: beta spreading (Eq. 9 max, K ..."
  const std::string after = "solve: beta spreading (Eq. 9 max, ";
  ASSERT_EQ(beta.rfind(after, 0), 0u) << beta;
  // As the shader (TLAB_HOST_PASSES=off), a part a step, as many as the solve ran.
  const auto steps = runCommand("TLAB_HOST_PASSES=off " + base + "--frames 1 --parts --json");
  ASSERT_EQ(steps.exitCode, 0) << steps.err;
  const auto stepsJson = nlohmann::json::parse(steps.out);
  const auto& shader = stepsJson["rows"][1];
  EXPECT_EQ(shader["operations"], smart["operations"]);
  EXPECT_EQ(shader["part_counts"]["solve beta frontier step"].get<int>(), std::stoi(beta.substr(after.size()))) << beta;
  EXPECT_FALSE(shader["part_counts"].contains("solve beta frontier on the host")) << shader;
  EXPECT_EQ(shader["part_counts"]["connect phase 1"], 1) << shader;
  EXPECT_EQ(shader["part_counts"]["connect phase 2"], 1) << shader;
  EXPECT_FALSE(shader["part_counts"].contains("connect phase 2 on the host")) << shader;
  for (const auto& row : stepsJson["rows"]) {  // the compose shaders blend, then their output is read back
    EXPECT_TRUE(row["part_counts"].contains("compose read-back")) << row;
    EXPECT_FALSE(row["part_counts"].contains("compose blend on the host")) << row;
  }

  const auto text = runCommand(base + "--frames 2 --parts");
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_TRUE(std::regex_search(text.out, std::regex("\n  parts: .*connect phase 1 on the host [0-9.]+ ms \\(1x\\), .*solve beta "
                                                     "frontier on the host [0-9.]+ ms \\(1x\\)")))
      << text.out;
  const auto wrong = runCommand("TLAB_HOST_PASSES=maybe " + base + "--frames 1");
  EXPECT_EQ(wrong.exitCode, 1);
  EXPECT_EQ(wrong.err, "tlab: error: TLAB_HOST_PASSES must be auto, on or off, not 'maybe'\n");
  const auto wrongRuns = runCommand("TLAB_DRAW_RUNS=lots " + base + "--frames 1");
  EXPECT_EQ(wrongRuns.exitCode, 1);
  EXPECT_EQ(wrongRuns.err, "tlab: error: TLAB_DRAW_RUNS must be auto or a whole number from 1 to 64, not 'lots'\n");
  EXPECT_EQ(runCommand(base + "--frames 1 --json").out.find("part_ms"), std::string::npos);  // only when asked for
  const auto alone = runCommand(kTlab + " bench render --parts");
  EXPECT_EQ(alone.exitCode, 1);
  EXPECT_EQ(alone.err, "tlab: error: --parts needs --scene\n");
}

// `tlab bench floor`: the bytes each pass moves, by its model (bench/measure/traffic_floor.hpp),
// on a scene whose fragments are known: 4 quads over every pixel of 32x24 give 3072 fragments of
// 3 words (depth, triangle, colour) for `constant`.
TEST(BenchCli, FloorCountsEachPassBytesAndMeasuresTheBandwidth) {
  const std::string floor = kTlab + " bench floor --scenes 'builtin:quad-stack?n=4&m=4' --styles constant,smart --size 32x24 "
                                    "--frames 1 --copy-mib 16 --gl osmesa --json";
  // With the shaders, constant's compose pass sorts each list as it blends: fill and compose.
  {
    const auto shaders = runCommand("TLAB_HOST_PASSES=off " + floor);
    ASSERT_EQ(shaders.exitCode, 0) << shaders.err;
    std::map<std::string, nlohmann::json> rows;
    nlohmann::json smartComposeShader;
    const auto parsed = nlohmann::json::parse(shaders.out);
    for (const auto& row : parsed["rows"]) {
      if (row["style"] == "constant") rows[row["pass"]] = row;
      if (row["style"] == "smart" && row["pass"] == "compose") smartComposeShader = row;
    }
    ASSERT_EQ(rows.size(), 2u) << shaders.out;
    EXPECT_EQ(rows["compose"]["bytes_read"].get<double>(), 32 * 24 * 24 + 3072 * 12);
    EXPECT_EQ(rows["compose"]["bytes_written"].get<double>(), 32 * 24 * 32);
    // smart's compose pass reads the colour plane and writes RGBA32F per pixel, then is read back
    EXPECT_EQ(smartComposeShader["bytes_read"].get<double>(), 32 * 24 * 24 + 3072 * 4) << shaders.out;
    EXPECT_EQ(smartComposeShader["bytes_written"].get<double>(), 32 * 24 * 32) << shaders.out;
  }
  const auto r = runCommand(floor);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["copy_bandwidth_1_thread"].get<double>(), 0);
  std::map<std::string, nlohmann::json> constant;
  nlohmann::json connect, smartSort, smartCompose;
  for (const auto& row : j["rows"]) {
    EXPECT_EQ(row["fragments"], 3072) << row;
    if (row["style"] == "constant") constant[row["pass"]] = row;
    if (row["style"] == "smart" && row["pass"] == "connect") connect = row;
    if (row["style"] == "smart" && row["pass"] == "sort") smartSort = row;
    if (row["style"] == "smart" && row["pass"] == "compose") smartCompose = row;
  }
  // llvmpipe runs the host passes: the colours sorted by host code (the colour plane alone), then
  // blended by host code into the image, one word a fragment (issue #29, twenty-eighth round).
  ASSERT_EQ(constant.size(), 3u) << j;
  const double pixels = 32 * 24, fragments = 3072, record = 12;
  EXPECT_EQ(constant["fill"]["bytes_read"].get<double>(), 0.0);
  EXPECT_EQ(constant["fill"]["bytes_written"].get<double>(), fragments * record + pixels * 8);
  EXPECT_EQ(constant["sort"]["bytes_read"].get<double>(), fragments * record + pixels * 8);
  EXPECT_EQ(constant["sort"]["bytes_written"].get<double>(), fragments * 4);
  EXPECT_EQ(constant["compose"]["bytes_read"].get<double>(), pixels * 8 + fragments * 4);
  EXPECT_EQ(constant["compose"]["bytes_written"].get<double>(), pixels * 16);
  EXPECT_GT(constant["compose"]["floor_ms"].get<double>(), 0.0);
  // Smart's records: 8 words (depth, triangle, colour, normal, ∇z, ids: 7 words padded to two
  // quads; the scene's quads are 4 components), which the fill and the sort move whole. Its connect
  // pass reads 5 of them (depth, ∇z, normal, ids), maxStep (2 floats a pixel, which smart's sort
  // writes beside the sorted records) and links of 4 words, and writes the links and the flags, and
  // of the fields only those that vary, as its compose reads only those: none here (α is s
  // everywhere by Eq. 4, and without a silhouette β and γ have no seed).
  ASSERT_FALSE(connect.is_null()) << j;
  const double smartRecord = 32;
  EXPECT_EQ(connect["bytes_read"].get<double>(), pixels * (8 + 8 + 8) + fragments * (5 * 4 + 16));
  EXPECT_EQ(connect["bytes_written"].get<double>(), fragments * (16 + 4));
  ASSERT_FALSE(smartSort.is_null()) << j;
  EXPECT_EQ(smartSort["bytes_read"].get<double>(), fragments * smartRecord + pixels * 8);
  // (and the colour words again: the colour plane smart's compose reads)
  EXPECT_EQ(smartSort["bytes_written"].get<double>(), fragments * smartRecord + pixels * 8 + fragments * 4);
  ASSERT_FALSE(smartCompose.is_null()) << j;
  EXPECT_EQ(smartCompose["bytes_read"].get<double>(), pixels * 8 + fragments * 1 * 4);  // blended by host code
  EXPECT_EQ(smartCompose["bytes_written"].get<double>(), pixels * 16);
  // The streaming rate of a copying compute shader, and each row's time over it.
  EXPECT_GT(j["gl_copy_bandwidth"].get<double>(), 0.0);
  const int words = j["gl_copy_words_per_invocation"];
  EXPECT_TRUE(words == 1 || words == 4 || words == 16) << words;
  EXPECT_GT(constant["compose"]["gl_ratio"].get<double>(), 0.0);
}

// The solve's row (issue #29): full-screen quads have no silhouette, so Eq. 9 has no seed and the
// solve moves nothing (no ratio); on a sphere the silhouette ring seeds β, and λβ = 1 lets the
// spreading reach nothing (1 − λ = 0), so only the seeds' links and values are read; with the
// defaults the fragments it reached are written once each. α diffusion (Eq. 5's adaptive α)
// counts full sweeps: 20 steps, 1 explicit dispatch each at λα = 1 with the normalized Laplacian,
// 4 sub-steps with the sum (λ ≤ 1/4); Eq. 8 spreading likewise for β and γ.
namespace {
// The row of `pass` in `tlab bench floor --styles smart` at 48x40 with `args`.
nlohmann::json smartFloorRow(const std::string& args, const std::string& pass) {
  const auto r = runCommand(kTlab + " bench floor --styles smart --size 48x40 --frames 1 --copy-mib 16 --gl osmesa --json " + args);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const auto& row : j["rows"])
    if (row["pass"] == pass) return row;
  ADD_FAILURE() << "no " << pass << " row: " << r.out;
  return nlohmann::json();
}
}  // namespace

TEST(BenchCli, FloorCountsTheSolveFromWhatItSpreadFromAndReached) {
  const auto solveRow = [](const std::string& args) { return smartFloorRow(args, "solve"); };
  const auto quads = solveRow("--scenes 'builtin:quad-stack?n=4&m=4'");
  EXPECT_EQ(quads["solve"]["beta_seeds"], 0);
  EXPECT_EQ(quads["bytes_read"].get<double>() + quads["bytes_written"].get<double>(), 0.0);
  EXPECT_TRUE(quads["ratio"].is_null()) << quads;

  const auto stopped = solveRow("--scenes builtin:sphere --set lambda_beta=1 --set lambda_gamma=1");
  const double seeds = stopped["solve"]["beta_seeds"];
  EXPECT_GT(seeds, 0.0);
  EXPECT_EQ(stopped["solve"]["beta_reached"], 0);
  EXPECT_EQ(stopped["bytes_read"].get<double>(), seeds * 20);  // links and value of each seed
  EXPECT_EQ(stopped["bytes_written"].get<double>(), 0.0);

  const auto spread = solveRow("--scenes builtin:sphere");
  EXPECT_EQ(spread["solve"]["beta_seeds"].get<double>(), seeds);
  const double reached = spread["solve"]["beta_reached"];
  EXPECT_GT(reached, 0.0);
  EXPECT_LT(reached, spread["fragments"].get<double>());
  EXPECT_EQ(spread["bytes_read"].get<double>(), (seeds + reached) * 20 + reached * 4);
  EXPECT_EQ(spread["bytes_written"].get<double>(), reached * 4);

  const double fragments = spread["fragments"];
  const auto adaptive = solveRow("--scenes builtin:sphere --set alpha_init=adaptive --set silhouettes=off --set halos=off");
  EXPECT_EQ(adaptive["solve"]["alpha_sweeps"], 20);
  EXPECT_EQ(adaptive["bytes_read"].get<double>(), 20 * fragments * 24);
  EXPECT_EQ(adaptive["bytes_written"].get<double>(), 20 * fragments * 4);
  const auto sum = solveRow("--scenes builtin:sphere --set alpha_init=adaptive --set laplacian=sum --set silhouettes=off --set halos=off");
  EXPECT_EQ(sum["solve"]["alpha_sweeps"], 80);
  const auto diffusion = solveRow("--scenes builtin:sphere --set spread=diffusion");
  EXPECT_EQ(diffusion["solve"]["beta_sweeps"], 20);
  EXPECT_EQ(diffusion["solve"]["gamma_sweeps"], 20);
  EXPECT_EQ(diffusion["bytes_written"].get<double>(), 40 * fragments * 4);
}

// What smart's compose reads of the fields (issue #29): around two nested spheres β (silhouettes)
// and γ (halos: the inner sphere's silhouette behind the outer surface) have seeds; α is read only
// where it varies (Eq. 5); a field switched off is not read, nor one without a seed (one sphere has
// silhouettes but nothing behind another surface's edge: no halo).
TEST(BenchCli, FloorCountsTheFieldsSmartsComposeReads) {
  const auto composeFields = [](const std::string& args) {
    const auto row = smartFloorRow(args, "compose");
    if (row.is_null()) return -1.0;
    const double pixels = 48 * 40, fragments = row["fragments"];
    // count and head per pixel (blended by host code on llvmpipe: no output to read back)
    return (row["bytes_read"].get<double>() - pixels * 8) / (fragments * 4) - 1;  // less the colour word
  };
  const std::string nested = "--scenes 'builtin:nested-spheres?n=2' ";
  EXPECT_EQ(composeFields(nested), 2.0);
  EXPECT_EQ(composeFields(nested + "--set alpha_init=adaptive"), 3.0);
  EXPECT_EQ(composeFields(nested + "--set halos=off"), 1.0);
  EXPECT_EQ(composeFields(nested + "--set silhouettes=off --set halos=off"), 0.0);
  EXPECT_EQ(composeFields("--scenes builtin:sphere"), 1.0);
}

// The connect pass's links: written once and read back once per fragment where phase 1 writes
// them as words; where it keeps them as bits of each pixel's pairs (lists longer than 8: six nested
// spheres, 12 layers at the centre), 16 bytes a pixel written and read instead, and the links
// written once. Where those bits join every fragment to the same layer all round (the 12-layer
// stack of full-screen quads), smart's frame leaves out phase 2: the pair words are written and
// nothing else.
TEST(BenchCli, FloorCountsTheConnectPassesLinksAsWordsOrAsPairBits) {
  const double pixels = 48 * 40;
  const auto stack = smartFloorRow("--scenes 'builtin:quad-stack?n=12'", "connect");
  const auto deep = smartFloorRow("--scenes 'builtin:nested-spheres?n=6'", "connect");
  const auto spheres = smartFloorRow("--scenes 'builtin:nested-spheres?n=2'", "connect");
  ASSERT_FALSE(stack.is_null() || deep.is_null() || spheres.is_null());
  EXPECT_NE(stack["model"].get<std::string>().find("phase 2 left out"), std::string::npos) << stack;
  EXPECT_NE(deep["model"].get<std::string>().find("links as bits of each pixel's pairs"), std::string::npos) << deep;
  EXPECT_EQ(deep["model"].get<std::string>().find("phase 2 left out"), std::string::npos) << deep;
  EXPECT_NE(spheres["model"].get<std::string>().find("links written once and read once"), std::string::npos) << spheres;
  const double stackFragments = stack["fragments"], deepFragments = deep["fragments"], sphereFragments = spheres["fragments"];
  EXPECT_EQ(stackFragments, 12 * pixels);
  // The pair words alone on the stack; elsewhere each fragment's links (16) and flags (4), β and
  // γ (seeded by the silhouettes: cleared, then 1 at the seeds), and the pair words where kept as bits.
  EXPECT_EQ(stack["bytes_written"].get<double>(), pixels * 16);
  EXPECT_EQ(deep["bytes_written"].get<double>(), deepFragments * 28 + pixels * 16);
  EXPECT_EQ(spheres["bytes_written"].get<double>(), sphereFragments * 28);
  // Count, head and maxStep per pixel (16), and count and head again for phase 2 (8); 5 words of
  // each record (depth, ∇z, normal, ids), and the pair words (16 a pixel) or each fragment's links (16).
  EXPECT_EQ(stack["bytes_read"].get<double>(), pixels * 16 + stackFragments * 20);
  EXPECT_EQ(deep["bytes_read"].get<double>(), pixels * 24 + deepFragments * 20 + pixels * 16);
  EXPECT_EQ(spheres["bytes_read"].get<double>(), pixels * 24 + sphereFragments * (20 + 16));
}

TEST(BenchCli, FloorRefusesASettingAStyleDoesNotHave) {
  const auto r = runCommand(kTlab + " bench floor --styles constant,smart --set lambda_beta=1 --gl osmesa");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("'constant' has no parameter 'lambda_beta'"), std::string::npos) << r.err;
}

// bench/gpu_table.sh, the one run a lab makes on its GPU (issue #29): every style on the torus,
// the 16-layer stack and the meshes given at each size, the floor of constant and smart, and the
// Markdown table of both. Here on Mesa's EGL at tiny sizes (the script's GL as written).
TEST(BenchCli, GpuTableScriptTimesEveryStyleOnTheScenesAndMeshesAndWritesTheTable) {
  const auto dir = freshDir("gpu_table");
  const std::string mesh = (dir / "spheres.gltf").string();
  ASSERT_EQ(runCommand(kTlab + " scene export builtin:nested-spheres?n=2 -o " + mesh).exitCode, 0);
  const std::string script = std::string(TLAB_SOURCE_DIR) + "/bench/gpu_table.sh";
  const auto out = dir / "out";
  const auto r = runCommand("SIZES=24x24,32x32 FRAMES=1 COPY_MIB=16 COMPARISONS=none bash " + script + " " + kTlab + " " +
                            out.string() + " " + mesh);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out / "failed.txt"));
  EXPECT_NE(readText((out / "machine.txt").string()).find("tlab: tlab "), std::string::npos);

  const auto all = nlohmann::json::parse(readText((out / "all.json").string()));
  std::vector<std::string> styles;
  for (const auto& row : all["rows"]) {
    EXPECT_FALSE(row.contains("error")) << row;
    const auto style = row["style"].get<std::string>();
    if (std::find(styles.begin(), styles.end(), style) == styles.end()) styles.push_back(style);
  }
  ASSERT_GE(styles.size(), 8u);
  EXPECT_EQ(all["rows"].size(), 3 * 2 * styles.size());  // torus, stack, the mesh; two sizes

  // The table: a line per scene and size with a time in every style's column, and both floors.
  const auto table = readText((out / "table.md").string());
  EXPECT_NE(r.out.find(table), std::string::npos) << "the table is printed";
  for (const std::string scene : {"builtin:torus?triangles=100000", "builtin:quad-stack?n=16", "spheres"})
    for (const std::string size : {"24²", "32²"}) {
      const auto at = table.find("| " + scene + " | " + size + " | ");
      ASSERT_NE(at, std::string::npos) << scene << " " << size << "\n" << table;
      const auto line = table.substr(at, table.find('\n', at) - at);
      EXPECT_EQ(std::count(line.begin(), line.end(), '|'), static_cast<long>(styles.size()) + 4) << line;
      EXPECT_EQ(line.find("failed"), std::string::npos) << line;
    }
  for (const std::string row : {"| builtin:quad-stack?n=16 | 24² | smart | connect | ", "| builtin:torus?triangles=100000 | 32² | constant | compose | "})
    EXPECT_NE(table.find(row), std::string::npos) << row << "\n" << table;
}

// A style that fails on a scene is a footnote with its error in the table, not a missing cell.
TEST(BenchCli, GpuTableNamesEachFailureAndStopsWithoutTheGlAsked) {
  const auto dir = freshDir("gpu_table_failures");
  const std::string script = std::string(TLAB_SOURCE_DIR) + "/bench/gpu_table.sh";
  const auto r = runCommand("bash " + script + " " + kTlab + " " + (dir / "out").string() + " " + (dir / "none.gltf").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("none.gltf: no such mesh file"), std::string::npos) << r.err;

  const auto noGl = runCommand("GL=egl:9 bash " + script + " " + kTlab + " " + (dir / "out").string());
  EXPECT_EQ(noGl.exitCode, 1);
  EXPECT_EQ(readText((dir / "out" / "failed.txt").string()), "tlab render --gl egl:9\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "all.json"));

  const nlohmann::json all = {
      {"frames", 3},
      {"gl", {{"renderer", "R"}, {"vendor", "V"}, {"version", "4.6"}, {"backend", "egl device"}}},
      {"reference_style", "constant"},
      {"rows",
       {{{"scene", "builtin:sphere"}, {"size", "2048x2048"}, {"style", "constant"}, {"fragments", 10}, {"frame_ms", 2.0},
         {"ratio_to_reference", 1.0}, {"pass_ms", {{"fill", 1.5}, {"compose", 0.5}}}},
        {{"scene", "builtin:sphere"}, {"size", "2048x2048"}, {"style", "smart"}, {"error", "too many fragments"}}}}};
  const auto tableDir = freshDir("gpu_table_footnote");
  std::ofstream((tableDir / "all.json").string()) << all.dump();
  const auto t = runCommand("python3 " + std::string(TLAB_SOURCE_DIR) + "/bench/gpu_table.py " + tableDir.string());
  ASSERT_EQ(t.exitCode, 0) << t.err;
  EXPECT_NE(t.out.find("| builtin:sphere | 2048² | 10 | 2.00 | failed (1) |"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("(1) builtin:sphere, 2048x2048, smart: too many fragments"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("| builtin:sphere | 2048² | fill 1.50, compose 0.50 | failed |"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("tlab on **R**"), std::string::npos) << t.out;
}

// A style that cannot run on one scene (here: more fragments than this GL's buffers may hold) is a
// row naming why; the other scenes' rows are still measured (bench/gpu_table.sh's 2048² floor).
TEST(BenchCli, FloorGoesOnPastAStyleThatCannotRunOnAScene) {
  const auto r = runCommand(kTlab + " bench floor --scenes builtin:sphere,builtin:quad-stack?n=64 --styles constant "
                                    "--size 1024x1024 --frames 1 --copy-mib 16 --gl osmesa --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::vector<std::string> sphere;
  std::string stackError;
  for (const auto& row : j["rows"]) {
    if (row["scene"] == "builtin:sphere") sphere.push_back(row["pass"].get<std::string>());
    if (row["scene"] == "builtin:quad-stack?n=64") stackError = row.value("error", std::string());
  }
  EXPECT_EQ(sphere, (std::vector<std::string>{"fill", "sort", "compose"}));  // the colours sorted by host code on llvmpipe
  EXPECT_NE(stackError.find("use a lower resolution"), std::string::npos) << r.out;
  const auto text = runCommand(kTlab + " bench floor --scenes builtin:quad-stack?n=64 --styles constant --size 1024x1024 "
                                       "--frames 1 --copy-mib 16 --gl osmesa");
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("\nbuiltin:quad-stack?n=64 "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find(" constant  failed: the illustration buffer needs "), std::string::npos) << text.out;
}
