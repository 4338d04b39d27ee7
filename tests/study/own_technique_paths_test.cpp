// A style file through every path that draws a stimulus (issue #28, "every path takes a style
// file"), end to end as a researcher runs them: `tlab run` in a GLFW window under an Xvfb the test
// starts (the autopilot answers, one trial a live orbit view), `tlab serve` (a participant's page
// fetching its stimulus), `tlab bench`, and `tlab render`/`tlab stimuli` through EGL and through
// OSMesa. Where a stimulus carries no marks (Elmqvist's counting task), what the path showed must
// be byte for byte the picture `tlab render --style FILE` draws headless, and differ from the
// built-in constant's. (`tlab simulate`, `design` and the stimulus sets' manifest and booklet are
// in own_technique_cli_test.cpp and external_set_images_cli_test.cpp; the live view's frames in
// live_view_style_file_gl_test.cpp.)
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "tests/study/serve_test_client.hpp"
#include "tests/study/served_study.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;
namespace fs = std::filesystem;

namespace {

const std::string kTlab = TLAB_EXE;
const std::string kStyles = std::string(TLAB_SOURCE_DIR) + "/examples/styles/";
const std::string kAbstract = "builtin:abstract?seed=3";

bool haveTool(const std::string& name) { return runCommand("command -v " + name).exitCode == 0; }
std::string sha256sum(const fs::path& file) { return runCommand("sha256sum " + quoted(file.string())).out.substr(0, 64); }

// A folder with styles/mine.glsl (the example depth-tinted alpha) and study.toml naming it.
fs::path studyFolder(const std::string& name, const std::string& experiment) {
  const auto dir = freshDir(name);
  fs::create_directories(dir / "styles");
  fs::copy_file(kStyles + "depth_tinted_alpha.glsl", dir / "styles" / "mine.glsl");
  std::ofstream(dir / "study.toml") << experiment;
  return dir;
}

// The picture of the abstract world `tlab render` draws headless at 128x128 in `style`.
std::string headlessPicture(const fs::path& dir, const std::string& style, const std::string& name) {
  const auto png = dir / (name + ".png");
  const auto r = runCommand(kTlab + " render " + quoted(kAbstract) + " --style " + quoted(style) + " --set alpha_far=0.7 --size 128x128 -o " +
                            quoted(png.string()));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return readText(png.string());
}

std::string headlessConstant(const fs::path& dir) {
  const auto png = dir / "constant.png";
  EXPECT_EQ(runCommand(kTlab + " render " + quoted(kAbstract) + " --style constant --size 128x128 -o " + quoted(png.string())).exitCode, 0);
  return readText(png.string());
}

const char* const kRunExperiment = R"(id = "own-run"
seed = 4
participants = 1
counterbalancing = "fixed"

[stimulus]
scene = "builtin:nested-spheres?n=3"
style = "styles/mine.glsl"
size = "128x128"
settings = ["alpha_far=0.7"]

[[tasks]]
id = "layer"
task = "layer-index"
time_limit = 60

[[tasks]]
id = "count"
task = "counting"
scene = "builtin:abstract?seed=3"
navigation = "orbit"
time_limit = 60
)";

}  // namespace

TEST(OwnTechniquePaths, RunShowsTheStyleFileInAWindowAndALiveView) {
  if (!haveTool("Xvfb")) GTEST_SKIP() << "needs Xvfb (scripts/setup.sh installs it)";
  const auto dir = studyFolder("own_run", kRunExperiment);
  const auto db = dir / "run.db";
  // Xvfb picks a free display itself (-displayfd); the autopilot answers through the real window.
  const std::string script =
      "Xvfb -displayfd 3 -screen 0 800x600x24 3>" + quoted((dir / "display").string()) + " >/dev/null 2>&1 & XPID=$!; "
      "for i in $(seq 100); do [ -s " + quoted((dir / "display").string()) + " ] && break; sleep 0.1; done; "
      "DISPLAY=:$(cat " + quoted((dir / "display").string()) + ") " + kTlab + " run " + quoted((dir / "study.toml").string()) +
      " --participant P1 --db " + quoted(db.string()) + " --size 640x480 --autopilot --autopilot-pace 0.01; RC=$?; kill $XPID; exit $RC";
  const auto r = runCommand("bash -c " + quoted(script));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("session finished: 2 of 2 trials answered"), std::string::npos) << r.out;
  EXPECT_EQ(queryCount(db.string(), "SELECT count(*) FROM sessions WHERE mode = 'autopilot'"), 1);
  // The orbit trial's stimulus (no marks) is the style file's picture, as drawn headless.
  tlab::study::Database d(db.string(), false);
  auto stored = d.prepare("SELECT stimulus_path, stimulus_sha256 FROM trials WHERE task_id = 'count'");
  ASSERT_TRUE(stored.step());
  const std::string shown = readText((dir / stored.text(0)).string());
  EXPECT_EQ(stored.text(1), sha256sum(dir / stored.text(0)));
  EXPECT_TRUE(shown == headlessPicture(dir, (dir / "styles" / "mine.glsl").string(), "mine")) << "the window's stimulus differs";
  EXPECT_FALSE(shown == headlessConstant(dir)) << "the style file made no difference";
  auto text = d.prepare("SELECT file_text FROM experiments");
  ASSERT_TRUE(text.step());
  EXPECT_NE(text.text(0).find("sha256 " + sha256sum(dir / "styles" / "mine.glsl")), std::string::npos);
}

TEST(OwnTechniquePaths, ServeSendsTheStyleFilesPictureToTheParticipantsPage) {
  const auto dir = studyFolder("own_serve", R"(id = "own-serve"
seed = 4
participants = 1
counterbalancing = "fixed"

[stimulus]
scene = "builtin:abstract?seed=3"
style = "styles/mine.glsl"
size = "128x128"
settings = ["alpha_far=0.7"]

[[tasks]]
id = "count"
task = "counting"
time_limit = 60
)");
  const std::string db = (dir / "serve.db").string();
  ServedStudy server((dir / "study.toml").string(), db, dir);
  PageClient page(server.port());
  const auto [status, token] = page.arrive("own-serve", "pid=p1");
  ASSERT_EQ(status, 303);
  const nlohmann::json trial = walk(page, token, page.api(token, "display", display()).body, 0).screens.back();
  ASSERT_EQ(trial["kind"], "trial") << trial.dump();
  const auto image = page.raw("/api/" + token + "/image/" + trial["image"]["sha256"].get<std::string>() + ".png");
  ASSERT_EQ(image->status, 200);
  EXPECT_TRUE(image->body == headlessPicture(dir, (dir / "styles" / "mine.glsl").string(), "mine")) << "the page's stimulus differs";
  EXPECT_FALSE(image->body == headlessConstant(dir));
  const Walk rest = walk(page, token, trial);
  EXPECT_EQ(rest.screens.back()["kind"], "end") << rest.screens.back().dump();
  server.stop(SIGTERM);
  EXPECT_EQ(queryCount(db, "SELECT count(*) FROM responses WHERE answered = 1"), 1);
}

TEST(OwnTechniquePaths, BenchTimesStyleFilesBesideTheBuiltInOnes) {
  const std::string depth = kStyles + "depth_tinted_alpha.glsl", halo = kStyles + "silhouette_halo.glsl";
  const auto r = runCommand(kTlab + " bench render --scene builtin:torus --size 64x64 --frames 1 --json --style constant," + depth + "," + halo);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["rows"].size(), 3u);
  EXPECT_FALSE(j["rows"][0].contains("style_sha256"));
  EXPECT_EQ(j["rows"][1]["style"], depth);
  EXPECT_EQ(j["rows"][1]["style_sha256"], sha256sum(depth));
  EXPECT_EQ(j["rows"][2]["style_sha256"], sha256sum(halo));
  for (const auto& row : j["rows"]) {
    EXPECT_FALSE(row.contains("error")) << row;
    EXPECT_EQ(row["fragments"], j["rows"][0]["fragments"]) << "the same fill for every style";
  }
  EXPECT_TRUE(j["rows"][2]["pass_ms"].contains("links+iterate")) << "the halo's per-fragment stage ran: " << j["rows"][2];
}

TEST(OwnTechniquePaths, EglAndOsmesaDrawEveryExampleStyleFileAlike) {
  const auto dir = freshDir("own_gl");
  for (const char* name : {"constant.glsl", "depth_tinted_alpha.glsl", "silhouette_halo.glsl"}) {
    std::map<std::string, std::string> pictures;
    for (const std::string gl : {"egl", "osmesa"}) {
      const auto png = dir / (gl + ".png"), stats = dir / (gl + ".json");
      const auto r = runCommand(kTlab + " render builtin:nested-spheres?n=3 --size 96x96 --style " + kStyles + name + " --gl " + gl + " -o " +
                                png.string() + " --stats-json " + stats.string());
      ASSERT_EQ(r.exitCode, 0) << name << " through " << gl << ": " << r.err;
      const auto j = nlohmann::json::parse(readText(stats.string()));
      EXPECT_EQ(j["gpu"]["backend"].get<std::string>().rfind(gl, 0), 0u) << j["gpu"];
      EXPECT_EQ(j["style_sha256"], sha256sum(kStyles + name));
      pictures[gl] = readText(png.string());
    }
    EXPECT_TRUE(pictures["egl"] == pictures["osmesa"]) << name << ": EGL and OSMesa differ";
  }
  // A stimulus set with a style file, through each backend by TLAB_GL: the same images.
  fs::create_directories(dir / "styles");
  fs::copy_file(kStyles + "silhouette_halo.glsl", dir / "styles" / "halo.glsl");
  std::ofstream(dir / "set.toml") << R"([set]
size = "96x96"
styles = ["styles/halo.glsl"]
booklet = false
[[scene]]
source = "builtin:nested-spheres?n=2"
probes = [{ task = "points", count = 2, seed = 1 }]
)";
  std::map<std::string, nlohmann::json> manifests;
  for (const std::string gl : {"egl", "osmesa"}) {
    const auto r = runCommand("TLAB_GL=" + gl + " " + kTlab + " stimuli " + (dir / "set.toml").string() + " -o " + (dir / gl).string() + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << gl << ": " << r.err;
    manifests[gl] = nlohmann::json::parse(readText((dir / gl / "manifest.json").string()));
    EXPECT_EQ(manifests[gl]["gl"]["backend"].get<std::string>().rfind(gl, 0), 0u) << manifests[gl]["gl"];
  }
  EXPECT_EQ(manifests["egl"]["stimuli"], manifests["osmesa"]["stimuli"]) << "the images' SHA-256 differ between EGL and OSMesa";
  EXPECT_EQ(manifests["egl"]["styles"][0]["style_sha256"], sha256sum(dir / "styles" / "halo.glsl"));
}
