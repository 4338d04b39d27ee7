// End to end: a researcher's own technique in an experiment — a style file named relative to the
// experiment file, checked at `tlab design` time (one line for a broken file), simulated, its
// SHA-256 recorded in the database, and an edit of the file making a new, unpooled version.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;
namespace fs = std::filesystem;

namespace {

const std::string kTlab = TLAB_EXE;

void expectOneLineError(const CommandResult& r, const std::string& part) {
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
}

std::string experimentText(const std::string& mineSettings) {
  return R"(id = "own"
seed = 3
participants = 2
counterbalancing = "williams"

[stimulus]
size = "96x96"
scene = "builtin:nested-spheres?n=3"

[[factors]]
name = "method"
levels = [
  { name = "constant", style = "constant", settings = ["alpha=0.3"] },
  { name = "mine", style = "styles/mine.glsl", settings = [)" + mineSettings + R"(] },
]

[[tasks]]
id = "layer"
task = "layer-index"
questions = 1
)";
}

std::string sha256sum(const std::string& path) { return runCommand("sha256sum " + quoted(path)).out.substr(0, 64); }

}  // namespace

TEST(OwnTechniqueCli, AStyleFileRunsInAnExperimentWithItsIdentityRecorded) {
  const auto dir = freshDir("own_technique");
  fs::create_directories(dir / "styles");
  const auto style = dir / "styles" / "mine.glsl";
  fs::copy_file(std::string(TLAB_SOURCE_DIR) + "/examples/styles/depth_tinted_alpha.glsl", style);
  const auto study = (dir / "study.toml").string();
  std::ofstream(study) << experimentText("\"alpha_far=0.7\"");
  // Run from another folder: the style path is relative to the experiment file, not to the shell.
  const std::string inTmp = "cd " + quoted(fs::temp_directory_path().string()) + " && ";
  const auto design = runCommand(inTmp + kTlab + " design " + study);
  ASSERT_EQ(design.exitCode, 0) << design.err;
  EXPECT_NE(design.out.find("style file styles/mine.glsl: sha256 " + sha256sum(style.string())), std::string::npos) << design.out;

  const auto db = (dir / "own.db").string();
  const auto sim = runCommand(inTmp + kTlab + " simulate " + study + " --participants 2 --db " + db);
  ASSERT_EQ(sim.exitCode, 0) << sim.err;
  const auto stored = runCommand("sqlite3 " + quoted(db) + " 'SELECT file_text FROM experiments'");
  ASSERT_EQ(stored.exitCode, 0) << stored.err;
  EXPECT_NE(stored.out.find("# tlab style file styles/mine.glsl = " + style.string() + " sha256 " + sha256sum(style.string())),
            std::string::npos) << stored.out;
  const auto trials = runCommand("sqlite3 " + quoted(db) + " 'SELECT count(*) FROM trials'");
  EXPECT_EQ(trials.out, "4\n") << trials.err;

  // Editing the style file makes a new version of the experiment whose design differs.
  std::string text = readText(style.string());
  text.replace(text.find("default = 0.6"), 13, "default = 0.5");
  std::ofstream(style) << text;
  const auto second = runCommand(inTmp + kTlab + " simulate " + study + " --participants 3 --first 3 --db " + db);
  ASSERT_EQ(second.exitCode, 0) << second.err;
  EXPECT_EQ(runCommand("sqlite3 " + quoted(db) + " 'SELECT count(*) FROM experiments'").out, "2\n");
  expectOneLineError(runCommand(kTlab + " analyze " + db), "versions whose designs differ");
  expectOneLineError(runCommand(kTlab + " export " + db + " --csv " + (dir / "csv").string()), "versions whose designs differ");
  const auto pooled = runCommand(kTlab + " export " + db + " --csv " + (dir / "csv").string() + " --pool-versions");  // only when asked
  ASSERT_EQ(pooled.exitCode, 0) << pooled.err;
  const auto rows = parseCsv(readText((dir / "csv" / "trials.csv").string()));
  EXPECT_EQ(rows.size(), 1u + 4u + 6u);  // the header, both versions' trials
}

TEST(OwnTechniqueCli, ABrokenStyleFileIsRefusedAtDesignTime) {
  const auto dir = freshDir("own_technique_broken");
  fs::create_directories(dir / "styles");
  const auto style = (dir / "styles" / "mine.glsl").string();
  std::string text = readText(std::string(TLAB_SOURCE_DIR) + "/examples/styles/depth_tinted_alpha.glsl");
  text.replace(text.find("float a = mix("), 14, "float a = mux(");
  std::ofstream(style) << text;
  int line = 1;
  for (std::size_t i = 0; i < text.find("mux("); ++i) line += text[i] == '\n';
  const auto study = (dir / "study.toml").string();
  std::ofstream(study) << experimentText("");
  expectOneLineError(runCommand(kTlab + " design " + study), fs::weakly_canonical(style).string() + ":" + std::to_string(line) + ": ");
  // A parameter out of its declared range names the experiment's line and field.
  std::ofstream(study) << experimentText("\"alpha_far=3\"");
  expectOneLineError(runCommand(kTlab + " design " + study),
                     "study.toml:14: factors[1].levels[2].settings: style 'depth-tinted-alpha' parameter 'alpha_far' = 3 is outside [0, 1]");
  // A missing file is named with where it was looked for.
  fs::remove(style);
  expectOneLineError(runCommand(kTlab + " design " + study), "factors[1].levels[2].style: cannot read the style file '" +
                                                                 fs::weakly_canonical(style).string() + "'");
}

TEST(OwnTechniqueCli, AStimulusSetTakesAStyleFileRelativeToTheSetFile) {
  const auto dir = freshDir("own_technique_set");
  fs::create_directories(dir / "styles");
  const auto style = dir / "styles" / "mine.glsl";
  fs::copy_file(std::string(TLAB_SOURCE_DIR) + "/examples/styles/silhouette_halo.glsl", style);
  const auto set = (dir / "set.toml").string();
  std::ofstream(set) << R"([set]
name = "own"
size = "96x96"
seed = 1
styles = ["constant", { name = "styles/mine.glsl", set = ["decay=0.2"] }]

[[scene]]
source = "builtin:nested-spheres?n=2"
probes = [{ task = "points", count = 2, seed = 1 }]
)";
  const auto out = dir / "out";
  const auto r = runCommand("cd " + quoted(fs::temp_directory_path().string()) + " && " + kTlab + " stimuli " + set + " -o " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto manifest = nlohmann::json::parse(readText((out / "manifest.json").string()));
  ASSERT_EQ(manifest["styles"].size(), 2u);
  EXPECT_FALSE(manifest["styles"][0].contains("style_sha256"));
  EXPECT_EQ(manifest["styles"][1]["style_sha256"], sha256sum(style.string()));
  ASSERT_EQ(manifest["stimuli"].size(), 2u);
  EXPECT_NE(manifest["stimuli"][1]["image"].get<std::string>().find("-mine"), std::string::npos) << manifest["stimuli"][1];
  EXPECT_TRUE(fs::exists(out / manifest["stimuli"][1]["image"].get<std::string>()));
}
