// End to end: the tools behind issue #29's comparison with VTK, run as a researcher runs them —
// bench/bench_meshes.py (public meshes and generated ones as glTF) and bench/vtk_compare.py (tlab's
// exact `constant` against VTK 9.1's dual depth peeling on any mesh and view). Structure and
// pictures only: speed is never asserted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/png_file.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;

namespace {

const std::string kTlab = TLAB_EXE;
const std::string kBench = std::string(TLAB_SOURCE_DIR) + "/bench/";

CommandResult meshes(const std::string& args) { return runCommand("python3 " + kBench + "bench_meshes.py " + args); }

// One line on stderr, naming `part`, and no Python traceback.
void expectOneLine(const CommandResult& r, const std::string& part, int exitCode, const std::string& what) {
  EXPECT_EQ(r.exitCode, exitCode) << what << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << what << "\n" << r.err;
  EXPECT_EQ(r.err.find("Traceback"), std::string::npos) << what << "\n" << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << what << "\n" << r.err;
}

// Writes `text` to dir/name; the file's path.
std::string writeFile(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  std::ofstream((dir / name).string()) << text;
  return (dir / name).string();
}

nlohmann::json statsOf(const std::string& scene, const std::string& camera, const std::filesystem::path& dir) {
  const auto stats = dir / "stats.json";
  const auto r = runCommand(kTlab + " render " + tlab::testing::quoted(scene) + " --camera " + tlab::testing::quoted(camera) + " --size 32x32 -o " +
                            tlab::testing::quoted((dir / "picture.png").string()) + " --stats-json " + tlab::testing::quoted(stats.string()));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return nlohmann::json::parse(readText(stats.string()));
}

// A unit cube as COFF: 8 coloured vertices, 6 coloured quads, comments and blank lines between.
const char* kCube =
    "COFF\n# a unit cube\n\n8 6 12\n"
    "-0.5 -0.5 -0.5 255 0 0 255\n0.5 -0.5 -0.5 255 0 0 255\n0.5 0.5 -0.5 255 0 0 255\n-0.5 0.5 -0.5 255 0 0 255\n"
    "-0.5 -0.5 0.5 255 0 0 255\n0.5 -0.5 0.5 255 0 0 255\n0.5 0.5 0.5 255 0 0 255\n-0.5 0.5 0.5 255 0 0 255\n"
    "4 0 3 2 1 0.5 0.5 0.5\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3  # the last face\n";

}  // namespace

TEST(BenchTools, MeshesAreWrittenAsTheySayAndTlabReadsThem) {
  const auto dir = freshDir("bench_meshes");
  const std::string view = "eye=0,0,5 target=0,0,0 up=0,1,0 fovy=40";
  // The deep stack: 3 layers of 2 x 2 quads, 24 triangles, 3 layers where they overlap.
  const auto stack = (dir / "stack.gltf").string();
  auto r = meshes("stack " + stack + " --layers 3 --grid 2");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, stack + ": 24 triangles\n");
  EXPECT_EQ(statsOf(stack, view, dir)["max_list_length"], 3);
  // The torus vtk_compare.py generates: 50 x 20 quads for 2000 triangles.
  const auto torus = (dir / "torus.gltf").string();
  r = meshes("torus " + torus + " --triangles 2000");
  EXPECT_EQ(r.out, torus + ": 2000 triangles\n") << r.err;
  EXPECT_GT(statsOf(torus, "eye=0,2.2,2.6 target=0,0,0 up=0,1,0 fovy=40", dir)["fragments"], 0);
  // An OFF file (here COFF, with colours, comments and quads): 6 quads fanned into 12 triangles, a
  // closed convex box that every ray through it crosses twice.
  const auto cube = (dir / "cube.gltf").string();
  r = meshes("off " + writeFile(dir, "cube.off", kCube) + " " + cube);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, cube + ": 12 triangles\n");
  const auto cubeStats = statsOf(cube, "eye=0.3,0.4,3 target=0,0,0 up=0,1,0 fovy=40", dir);
  EXPECT_EQ(cubeStats["max_list_length"], 2);
  EXPECT_DOUBLE_EQ(cubeStats["mean_covered_list_length"].get<double>(), 2.0);
  // Newell's teapot is read from freeglut's header; here one flat patch in its format, whose
  // evenly spaced control points make the bicubic patch the unit square: (3 + 1)² points, 18 triangles.
  std::ofstream header((dir / "fg_teapot_data.h").string());
  header << "/* Martin Newell's teapot, one patch */\n16 0 1 0\n";
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) header << 4 * i + j + 1 << " " << j / 3.0 << " " << i / 3.0 << " 0\n";
  header << "1, 2, 3, 4, 5, 6, 7, 8,\n9, 10, 11, 12, 13, 14, 15, 16,\n";
  header.close();
  const auto patch = (dir / "patch.gltf").string();
  r = meshes("teapot " + (dir / "fg_teapot_data.h").string() + " " + patch + " --steps 3");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, patch + ": 18 triangles\n");
  const auto gltf = nlohmann::json::parse(readText(patch));
  EXPECT_EQ(gltf["accessors"][0]["count"], 16);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(gltf["accessors"][0]["min"][k].get<double>(), 0.0, 1e-6);
    EXPECT_NEAR(gltf["accessors"][0]["max"][k].get<double>(), k < 2 ? 1.0 : 0.0, 1e-6);
  }
}

// A public mesh as the README's table names it: fandisk (CAD) from Debian's CGAL data (libcgal-demo).
TEST(BenchTools, TheReadmesPublicMeshHasItsTriangles) {
  const std::string data = "/usr/share/doc/libcgal-dev/data.tar.gz";
  if (!std::filesystem::exists(data)) GTEST_SKIP() << "needs libcgal-demo's " << data << " (scripts/setup.sh installs it)";
  const auto dir = freshDir("bench_meshes_fandisk");
  ASSERT_EQ(runCommand("tar -xzf " + data + " -C " + dir.string() + " data/meshes/fandisk.off").exitCode, 0);
  const auto out = (dir / "fandisk.gltf").string();
  const auto r = meshes("off " + (dir / "data/meshes/fandisk.off").string() + " " + out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, out + ": 12946 triangles\n");  // as the README's table says
}

TEST(BenchTools, MeshesRefuseBadFilesInOneLineNamingFileAndLine) {
  const auto dir = freshDir("bench_meshes_bad");
  const std::string out = (dir / "out.gltf").string();
  const struct {
    std::string args, part;
  } cases[] = {
      {"off " + writeFile(dir, "ply.off", "ply\nformat ascii 1.0\n") + " " + out, "ply.off: line 1: not an OFF file"},
      {"off " + writeFile(dir, "short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n") + " " + out, "short.off: ends before vertex 3 of 3"},
      {"off " + writeFile(dir, "range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n") + " " + out,
       "range.off: line 6: vertex index 7 out of range (the file has 3 vertices)"},
      {"off " + writeFile(dir, "word.off", "OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n") + " " + out,
       "word.off: line 4: a vertex (x y z) expected, found '1 zero 0'"},
      {"off " + writeFile(dir, "counts.off", "OFF\n# counts\nthree 1 0\n") + " " + out, "counts.off: line 3: the vertex and face counts"},
      {"off " + (dir / "none.off").string() + " " + out, "none.off: No such file or directory"},
      {"teapot " + writeFile(dir, "other.h", "/* no teapot here */\n") + " " + out, "other.h: no \"Martin Newell's teapot\""},
  };
  for (const auto& c : cases) expectOneLine(meshes(c.args), c.part, 1, c.args);
  EXPECT_FALSE(std::filesystem::exists(out)) << "no file is written from a bad mesh";
  expectOneLine(meshes("stack " + out + " --layers 0"), "--layers must be at least 1", 2, "--layers 0");
}

namespace {

// VTK and xvfb-run are in scripts/setup.sh's packages, so CI runs these tests; a machine set up
// without them skips, saying what to install.
bool haveVtk() {
  return runCommand("command -v xvfb-run && /usr/bin/python3 -c 'import vtk'").exitCode == 0;
}

CommandResult vtkCompare(const std::string& args) {
  return runCommand("xvfb-run -a -s '-screen 0 640x480x24' /usr/bin/python3 " + kBench + "vtk_compare.py --tlab " + kTlab +
                    " --size 48 --frames 1 --modes dual-peeling " + args);
}

// The share of pixels covered (not the white background) in both pictures among those covered
// in either: 1 where both programs drew the same silhouette from the same view.
double coverageAgreement(const std::string& a, const std::string& b) {
  const auto ia = tlab::core::readPngFile(a), ib = tlab::core::readPngFile(b);
  if (!ia || !ib || ia->width != ib->width || ia->height != ib->height) return 0;
  const auto covered = [](const glm::vec4& p) { return std::min({p.r, p.g, p.b}) < 0.97f; };
  int both = 0, either = 0;
  for (std::size_t i = 0; i < ia->pixels.size(); ++i) {
    const bool ca = covered(ia->pixels[i]), cb = covered(ib->pixels[i]);
    both += ca && cb;
    either += ca || cb;
  }
  return either == 0 ? 0 : double(both) / either;
}

}  // namespace

// Any mesh (an OFF file, the generated torus, a GLB of several objects with their nodes) and its
// view: both programs timed in alternating rounds, the table with both times and their ratio, the
// fragments tlab counts on that view, and pictures that show both drew the same silhouette.
TEST(BenchTools, VtkCompareTimesTlabAndVtkOnAnyMeshFromTheSameView) {
  if (!haveVtk()) GTEST_SKIP() << "needs xvfb-run and Debian's python3-vtk9 (scripts/setup.sh installs both)";
  const auto dir = freshDir("vtk_compare");
  const auto cubeOff = writeFile(dir, "cube.off", kCube);
  const auto glb = (dir / "spheres.glb").string();
  ASSERT_EQ(runCommand(kTlab + " scene export builtin:nested-spheres?n=2 -o " + glb).exitCode, 0);
  const auto images = dir / "images";
  const auto r = vtkCompare("--rounds 2 --mesh " + cubeOff + " --mesh torus --triangles 2000 --mesh " +
                            glb + " --images " + images.string());
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;

  // Each mesh's camera, as printed, and its row in the table.
  const std::regex cameraLine(R"(mesh: (.*); camera: (.*))");
  std::vector<std::string> cameras;
  for (std::sregex_iterator m(r.out.begin(), r.out.end(), cameraLine), end; m != end; ++m) cameras.push_back((*m)[2]);
  ASSERT_EQ(cameras.size(), 3u) << r.out;
  const std::regex row(R"(\| (.+?) \| (\d+) \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \|)");
  std::vector<std::smatch> rows;
  for (std::sregex_iterator m(r.out.begin(), r.out.end(), row), end; m != end; ++m) rows.push_back(*m);
  ASSERT_EQ(rows.size(), 3u) << r.out;
  const std::string files[] = {"cube.gltf", "torus.gltf", "spheres.glb"};
  const std::string scenes[] = {"", "", glb};
  for (int i = 0; i < 3; ++i) {
    for (const std::string round : {"round 1: ", "round 2: "}) {
      EXPECT_NE(r.out.find(round + files[i] + ": tlab constant"), std::string::npos) << files[i] << "\n" << r.out;
      EXPECT_NE(r.out.find(round + files[i] + ": VTK dual-peeling"), std::string::npos) << files[i] << "\n" << r.out;
    }
    // The ratio is tlab's time over VTK's, as printed (each to 0.1 ms).
    const double tlabMs = std::stod(rows[i][3]), vtkMs = std::stod(rows[i][4]), ratio = std::stod(rows[i][5]);
    ASSERT_GT(tlabMs, 0);
    ASSERT_GT(vtkMs, 0.05);
    EXPECT_GE(ratio, (tlabMs - 0.05) / (vtkMs + 0.05) - 0.005) << rows[i][0];
    EXPECT_LE(ratio, (tlabMs + 0.05) / (vtkMs - 0.05) + 0.005) << rows[i][0];
    // Both pictures of the view: the same silhouette.
    const auto tlabPng = (images / (files[i] + "-tlab.png")).string();
    const auto vtkPng = (images / (files[i] + "-vtk-dual-peeling.png")).string();
    EXPECT_GT(coverageAgreement(tlabPng, vtkPng), 0.9) << tlabPng << " against " << vtkPng;
  }
  // The fragments are tlab's on that view: the GLB as `tlab render` counts them from the printed camera.
  const auto stats = dir / "spheres.json";
  ASSERT_EQ(runCommand(kTlab + " render " + glb + " --camera " + tlab::testing::quoted(cameras[2]) + " --size 48x48 --set alpha=0.3 -o " +
                       (dir / "spheres.png").string() + " --stats-json " + stats.string())
                .exitCode,
            0);
  EXPECT_EQ(std::to_string(nlohmann::json::parse(readText(stats.string()))["fragments"].get<long>()), rows[2][2].str());
  EXPECT_EQ(rows[0][1].str(), cubeOff + " as glTF, 12 triangles");
}

TEST(BenchTools, VtkCompareRefusesBadInputInOneLine) {
  if (!haveVtk()) GTEST_SKIP() << "needs xvfb-run and Debian's python3-vtk9 (scripts/setup.sh installs both)";
  const auto dir = freshDir("vtk_compare_bad");
  const struct {
    std::string args, part;
    int exitCode;
  } cases[] = {
      {"--mesh " + (dir / "none.gltf").string(), "--mesh " + (dir / "none.gltf").string() + ": no such file", 2},
      {"--mesh " + writeFile(dir, "range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n"), "range.off: line 6: vertex index 9", 1},
      {"--mesh " + writeFile(dir, "broken.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": ["),
       "broken.gltf: VTK's glTF reader found no triangles", 1},
      {"--modes peeling", "--modes: 'peeling' is not dual-peeling or weighted-oit", 2},
      {"--camera 'eye=0,1 target=0,0,0 up=0,1,0 fovy=40'", "--camera: eye= needs 3 numbers", 2},
      {"--triangles 2000 --gl egl:9", "the generated torus: tlab bench render failed: tlab: error: EGL device 9", 1},
  };
  for (const auto& c : cases) expectOneLine(vtkCompare("--rounds 1 " + c.args), c.part, c.exitCode, c.args);
}

// bench/smart_ratio.sh, which measured issue #29's smart-against-constant goals: builds timed in
// alternating rounds, each round's ratio from its own two frames, each build's best frames over
// the rounds and their ratio, and the median and range of the rounds' own ratios.
TEST(BenchTools, SmartRatioAlternatesBuildsAndPrintsEachRatioFromItsFrames) {
  const auto dir = freshDir("smart_ratio");
  std::filesystem::create_directories(dir / "other");
  std::filesystem::create_symlink(kTlab, dir / "other" / "tlab");
  const std::string other = (dir / "other" / "tlab").string();
  const auto r = runCommand("cd " + dir.string() + " && SCENES='builtin:sphere builtin:cube' SIZE=24x24 FRAMES=1 bash " + kBench +
                            "smart_ratio.sh 2 " + kTlab + " other/tlab");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const std::regex roundLine(R"(round (\d)\t(\S+)\t(\S+)\tsmart/constant ([\d.]+)\tconstant ([\d.]+) ms \(.*fill.*\)\tsmart ([\d.]+) ms \(.*connect.*\)\tload)");
  struct Round {
    int round;
    std::string scene, build;
    double ratio, constant, smart;
  };
  std::vector<Round> rounds;
  for (std::sregex_iterator m(r.out.begin(), r.out.end(), roundLine), end; m != end; ++m)
    rounds.push_back({std::stoi((*m)[1]), (*m)[2], (*m)[3], std::stod((*m)[4]), std::stod((*m)[5]), std::stod((*m)[6])});
  ASSERT_EQ(rounds.size(), 8u) << r.out;
  const std::string scenes[] = {"builtin:sphere", "builtin:cube"}, builds[] = {kTlab, "other/tlab"};
  for (std::size_t i = 0; i < rounds.size(); ++i) {  // round by round, scene by scene, build by build
    EXPECT_EQ(rounds[i].round, int(i / 4) + 1);
    EXPECT_EQ(rounds[i].scene, scenes[i / 2 % 2]);
    EXPECT_EQ(rounds[i].build, builds[i % 2]);
    ASSERT_GT(rounds[i].constant, 0.05) << r.out;
    // The ratio of the two frames, each printed to 0.1 ms.
    const auto& x = rounds[i];
    EXPECT_GE(x.ratio, (x.smart - 0.05) / (x.constant + 0.05) - 0.005) << r.out;
    EXPECT_LE(x.ratio, (x.smart + 0.05) / (x.constant - 0.05) + 0.005) << r.out;
  }
  for (int s = 0; s < 2; ++s)
    for (int b = 0; b < 2; ++b) {
      double c = 1e9, sm = 1e9, lo = 1e9, hi = 0;
      std::vector<double> own;
      for (const auto& x : rounds)
        if (x.scene == scenes[s] && x.build == builds[b]) {
          c = std::min(c, x.constant), sm = std::min(sm, x.smart);
          lo = std::min(lo, x.ratio), hi = std::max(hi, x.ratio);
        }
      char best[256];
      std::snprintf(best, sizeof best, "  %s\t%s\tconstant %.1f ms\tsmart %.1f ms\t", scenes[s].c_str(), builds[b].c_str(), c, sm);
      EXPECT_NE(r.out.find(best), std::string::npos) << best << "\n" << r.out;
      const auto at = r.out.find("the rounds' own smart / constant");
      ASSERT_NE(at, std::string::npos) << r.out;
      const auto line = r.out.find("  " + scenes[s] + "\t" + builds[b] + "\t", at);
      ASSERT_NE(line, std::string::npos) << r.out;
      const std::string text = r.out.substr(line, r.out.find('\n', line) - line);
      std::smatch m;
      ASSERT_TRUE(std::regex_search(text, m, std::regex(R"(\t([\d.]+) \(([\d.]+), ([\d.]+)\)$)"))) << text;
      // (each printed to 0.01, from frames printed to 0.001 ms: a few thousandths apart at most)
      EXPECT_NEAR(std::stod(m[2]), lo, 0.011) << text;
      EXPECT_NEAR(std::stod(m[3]), hi, 0.011) << text;
      EXPECT_NEAR(std::stod(m[1]), (lo + hi) / 2, 0.011) << text;  // two rounds: the median is their mean
    }
  expectOneLine(runCommand("bash " + kBench + "smart_ratio.sh 0"), "ROUNDS must be a whole number of at least 1", 2, "0");
  expectOneLine(runCommand("bash " + kBench + "smart_ratio.sh 1 " + (dir / "none").string()), "none: not an executable tlab", 2,
                "none");
}

// scripts/hash_render_outputs.sh, with which every change to the renderer shows its pictures
// byte-identical (issue #29): a hash for each picture it names, each the hash of the PNG `tlab
// render` writes for it, none failed, the meshes given included; a bad tlab or mesh is one line.
TEST(BenchTools, HashRenderOutputsHashesWhatTlabRendersUnderEachName) {
  const auto dir = freshDir("hash_render_outputs");
  const std::string mesh = (dir / "ball.gltf").string();
  ASSERT_EQ(runCommand(kTlab + " scene export builtin:sphere -o " + mesh).exitCode, 0);
  const std::string script = std::string(TLAB_SOURCE_DIR) + "/scripts/hash_render_outputs.sh";
  const auto r = runCommand("TLAB_HASH_MESHES=" + mesh + " bash " + script + " " + kTlab);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::map<std::string, std::string> hashes;
  std::istringstream lines(r.out);
  const std::regex line(R"(([0-9a-f]{64})  (\S+))");
  for (std::string l; std::getline(lines, l);) {
    std::smatch m;
    ASSERT_TRUE(std::regex_match(l, m, line)) << "not a hash and a name (or failed): " << l;
    EXPECT_TRUE(hashes.emplace(m[2], m[1]).second) << "a name twice: " << l;
  }
  for (const std::string name : {"constant-sphere", "smart-quad-stack?n=8", "smart-pow-torus", "constant-list-cube",
                                 "smart-512-quad-stack?n=16", "constant-list-pbr-torus", "iris-peel-window_layers=2-torus",
                                 "constant-512-abstract", "constant-ball.gltf", "smart-ball.gltf"})
    EXPECT_TRUE(hashes.count(name)) << name << "\n" << r.out;
  EXPECT_GE(std::count_if(hashes.begin(), hashes.end(), [](const auto& h) { return h.first.size() > 4 && h.first.ends_with(".png"); }),
            10)
      << "tlab figures' PNGs";
  // Each hash is that of the picture tlab renders for the name's scene, style and size.
  const auto sha = [&](const std::string& args) {
    const auto png = (dir / "direct.png").string();
    const auto rendered = runCommand(kTlab + " " + args + " -o " + png);
    EXPECT_EQ(rendered.exitCode, 0) << rendered.err;
    return runCommand("sha256sum < " + png + " | cut -d' ' -f1").out.substr(0, 64);
  };
  EXPECT_EQ(hashes["constant-sphere"], sha("render builtin:sphere --style constant --size 160x128"));
  EXPECT_EQ(hashes["smart-ball.gltf"], sha("render " + mesh + " --style smart --size 384x384"));
  EXPECT_NE(hashes["constant-sphere"], hashes["smart-sphere"]);

  expectOneLine(runCommand("bash " + script + " " + (dir / "none").string()), "none: not an executable tlab", 2, "tlab");
  expectOneLine(runCommand("TLAB_HASH_MESHES=" + (dir / "none.gltf").string() + " bash " + script + " " + kTlab),
                "TLAB_HASH_MESHES: " + (dir / "none.gltf").string() + ": no such file", 2, "mesh");
}
