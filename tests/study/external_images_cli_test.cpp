// End to end with a real other renderer: a scene exported by `tlab scene export`, drawn by VTK
// (scripts/render_with_vtk.py, Debian's python3-vtk9 under xvfb-run) from the exported camera,
// registered as a factor level { images = "renders/{scene}.png" }, passing the alignment check at
// `tlab design` time and simulated end to end; the same images from a shifted camera, or flipped,
// are refused with their IoU and the likely cause.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/vtk_images.hpp"

using namespace tlab::testing;
namespace fs = std::filesystem;

namespace {

const std::string kTlab = TLAB_EXE;

std::string experimentText(const std::string& images) {
  return R"(id = "theirs"
seed = 5
participants = 2
counterbalancing = "williams"

[stimulus]
size = "128x96"

[[factors]]
name = "method"
levels = [
  { name = "constant", style = "constant" },
  { name = "theirs", images = ")" + images + R"(" },
]

[[factors]]
name = "scene"
levels = [{ name = "torus", scene = "builtin:torus" }, { name = "spheres", scene = "builtin:nested-spheres?n=2" }]

[[tasks]]
id = "layer"
task = "layer-index"
questions = 1
)";
}

// Exports each scene and draws it with VTK into dir/folder/NAME.png (extra: render_with_vtk.py options).
void drawBothScenes(const fs::path& dir, const std::string& folder, const std::string& extra) {
  for (const auto& [name, scene] : {std::pair{"torus", "builtin:torus"}, std::pair{"spheres", "builtin:nested-spheres?n=2"}})
    ASSERT_EQ(tlab::testing::drawWithVtk(scene, "128x96", "", dir / folder / (std::string(name) + ".png"), extra), "");
}

double iouIn(const std::string& text) {
  std::smatch m;
  return std::regex_search(text, m, std::regex(R"(IoU ([0-9.]+))")) ? std::stod(m[1]) : -1.0;
}

}  // namespace

TEST(ExternalImagesCli, VtkImagesOfTheExportedSceneAlignAndRunEndToEnd) {
  const auto dir = freshDir("external_images");
  drawBothScenes(dir, "renders", "");
  const auto study = (dir / "study.toml").string();
  std::ofstream(study) << experimentText("renders/{scene}.png");
  const auto design = runCommand(kTlab + " design " + study);
  ASSERT_EQ(design.exitCode, 0) << design.err;
  std::cout << design.out.substr(0, design.out.find("counterbalancing"));
  EXPECT_NE(design.out.find("renders/torus.png: aligned with builtin:torus (IoU"), std::string::npos) << design.out;
  EXPECT_NE(design.out.find("renders/spheres.png: aligned with builtin:nested-spheres?n=2 (IoU"), std::string::npos) << design.out;
  EXPECT_GE(iouIn(design.out), 0.98);
  const auto db = (dir / "theirs.db").string();
  const auto sim = runCommand(kTlab + " simulate " + study + " --participants 2 --db " + db);
  ASSERT_EQ(sim.exitCode, 0) << sim.err;
  EXPECT_EQ(runCommand("sqlite3 " + quoted(db) + " 'SELECT count(*) FROM trials'").out, "8\n");
  // Each raw image's identity is stored with the experiment's text.
  const auto stored = runCommand("sqlite3 " + quoted(db) + " 'SELECT file_text FROM experiments'").out;
  for (const char* name : {"torus", "spheres"}) {
    const auto image = (dir / "renders" / (std::string(name) + ".png")).string();
    const std::string sha = runCommand("sha256sum " + quoted(image)).out.substr(0, 64);  // coreutils, not tlab's SHA-256
    EXPECT_NE(stored.find("# tlab image file renders/" + std::string(name) + ".png = " + image + " sha256 " + sha), std::string::npos) << stored;
    EXPECT_NE(design.out.find("sha256 " + sha), std::string::npos) << design.out;
  }
}

TEST(ExternalImagesCli, AReRenderedImageMakesANewVersionPooledOnlyWhenAsked) {
  const auto dir = freshDir("external_images_version");
  drawBothScenes(dir, "renders", "");
  const auto study = (dir / "study.toml").string();
  std::ofstream(study) << experimentText("renders/{scene}.png");
  const auto db = (dir / "theirs.db").string();
  ASSERT_EQ(runCommand(kTlab + " simulate " + study + " --participants 2 --db " + db).exitCode, 0);
  ASSERT_EQ(runCommand(kTlab + " simulate " + study + " --participants 2 --first 3 --db " + db).exitCode, 0);
  EXPECT_EQ(runCommand("sqlite3 " + quoted(db) + " 'SELECT count(*) FROM experiments'").out, "1\n") << "the same images: the same version";
  // The researcher draws the torus again from a camera moved by 1/1000: other bytes, still aligned.
  ASSERT_EQ(drawWithVtk("builtin:torus", "128x96", "", dir / "renders" / "torus.png", "--shift 0.001,0,0"), "");
  const auto third = runCommand(kTlab + " simulate " + study + " --participants 2 --first 5 --db " + db);
  ASSERT_EQ(third.exitCode, 0) << third.err;
  EXPECT_EQ(runCommand("sqlite3 " + quoted(db) + " 'SELECT count(*) FROM experiments'").out, "2\n");
  const std::string csv = " --csv " + quoted((dir / "csv").string());
  const auto refused = runCommand(kTlab + " export " + db + csv);
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_NE(refused.err.find("versions whose designs differ"), std::string::npos) << refused.err;
  const auto pooled = runCommand(kTlab + " export " + db + csv + " --pool-versions");
  ASSERT_EQ(pooled.exitCode, 0) << pooled.err;
  EXPECT_EQ(parseCsv(readText((dir / "csv" / "trials.csv").string())).size(), 1u + 3 * 8u);  // the header, three simulations' trials
}

TEST(ExternalImagesCli, ImagesFromAShiftedOrFlippedCameraAreRefusedWithTheirIoU) {
  const auto dir = freshDir("external_images_refused");
  drawBothScenes(dir, "shifted", "--shift 0.25,0,0");
  drawBothScenes(dir, "flipped", "--flip");
  const auto study = (dir / "study.toml").string();
  std::ofstream(study) << experimentText("shifted/{scene}.png");
  const auto shifted = runCommand(kTlab + " design " + study);
  std::cout << shifted.err;
  EXPECT_EQ(shifted.exitCode, 1);
  EXPECT_EQ(std::count(shifted.err.begin(), shifted.err.end(), '\n'), 1) << shifted.err;
  EXPECT_TRUE(std::regex_search(shifted.err, std::regex(R"(shifted/(torus|spheres)\.png: IoU)"))) << shifted.err;
  EXPECT_LT(iouIn(shifted.err), 0.98);
  EXPECT_NE(shifted.err.find("likely cause: shifted camera"), std::string::npos) << shifted.err;
  std::ofstream(study) << experimentText("flipped/{scene}.png");
  const auto flipped = runCommand(kTlab + " design " + study);
  std::cout << flipped.err;
  EXPECT_EQ(flipped.exitCode, 1);
  EXPECT_NE(flipped.err.find("likely cause: vertical flip"), std::string::npos) << flipped.err;
}

TEST(ExternalImagesCli, ATaskExploredLiveCannotShowImagesAndIsRefusedAtDesignTime) {
  const auto dir = freshDir("external_images_live");
  const auto study = (dir / "study.toml").string();
  std::ofstream(study) << R"(id = "live-theirs"
seed = 1
participants = 1
counterbalancing = "fixed"

[stimulus]
size = "128x96"
scene = "builtin:abstract?seed=3"

[[factors]]
name = "method"
levels = [{ name = "constant", style = "constant" }, { name = "theirs", images = "renders/abstract.png" }]

[[tasks]]
id = "count"
task = "counting"
navigation = "orbit"
)";
  const auto r = runCommand(kTlab + " design " + study);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("study.toml:17: tasks[1].navigation: navigation = \"orbit\" draws tlab's live view of the scene, which cannot show "
                       "the images from another renderer of method=theirs"),
            std::string::npos)
      << r.err;
}
