// End to end: images from another renderer in a stimulus set. Each scene view is exported by
// `tlab scene export` and drawn by VTK (tests/support/vtk_images.hpp); the set names them with
// { name = "theirs", images = "renders/{scene}-{view}.png" } beside a built-in style and a style
// file. `tlab stimuli` checks each image against tlab's coverage of its view, draws the marks of
// tlab's questions over it, records the raw image's SHA-256 and IoU in the manifest, and puts it
// in the booklet; an image from a shifted camera is refused with its IoU before anything is drawn.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>

#include <nlohmann/json.hpp>

#include "analysis/document_text.hpp"
#include "core/png_file.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/vtk_images.hpp"

using namespace tlab::testing;
namespace fs = std::filesystem;

namespace {

const std::string kTlab = TLAB_EXE;
const std::string kSide = "eye=2,1.5,3 target=0,0,0 up=0,1,0 fovy=40";

std::string setText(const std::string& images) {
  return R"([set]
name = "theirs"
size = "128x96"
seed = 2
styles = ["constant", "styles/mine.glsl", { name = "theirs", images = ")" + images + R"(" }]

[[scene]]
source = "builtin:torus"
views = [{}, { name = "side", camera = ")" + kSide + R"(" }]
probes = [{ task = "layer-index", count = 1 }]

[[scene]]
source = "builtin:nested-spheres?n=2"
name = "spheres"
probes = [{ task = "points", count = 2 }]
)";
}

std::string sha256sum(const fs::path& file) { return runCommand("sha256sum " + quoted(file.string())).out.substr(0, 64); }

// dir/FOLDER/{torus-v1, torus-side, spheres-v1}.png drawn by VTK from tlab's cameras of the views.
void drawViews(const fs::path& dir, const std::string& folder) {
  ASSERT_EQ(drawWithVtk("builtin:torus", "128x96", "", dir / folder / "torus-v1.png"), "");
  ASSERT_EQ(drawWithVtk("builtin:torus", "128x96", kSide, dir / folder / "torus-side.png"), "");
  ASSERT_EQ(drawWithVtk("builtin:nested-spheres?n=2", "128x96", "", dir / folder / "spheres-v1.png"), "");
}

fs::path setFolder(const std::string& name) {
  const auto dir = freshDir(name);
  fs::create_directories(dir / "styles");
  fs::copy_file(std::string(TLAB_SOURCE_DIR) + "/examples/styles/depth_tinted_alpha.glsl", dir / "styles" / "mine.glsl");
  return dir;
}

CommandResult runSet(const fs::path& set, const fs::path& out) {  // from another folder: paths are relative to the set file
  return runCommand("cd " + quoted(fs::temp_directory_path().string()) + " && " + kTlab + " stimuli " + quoted(set.string()) + " -o " +
                    quoted(out.string()) + " --quiet");
}

// The shown image equals the given one except where a mark is drawn: at every visible mark's
// pixel, and on at most a fifth of the picture.
void expectMarksOverTheImage(const fs::path& shown, const fs::path& given, const nlohmann::json& probes) {
  const auto a = tlab::core::readPngFile(shown.string()), b = tlab::core::readPngFile(given.string());
  ASSERT_TRUE(a && b);
  ASSERT_EQ(a->pixels.size(), b->pixels.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a->pixels.size(); ++i) differ += a->pixels[i] != b->pixels[i];
  EXPECT_GT(differ, 0u);
  EXPECT_LT(differ, a->pixels.size() / 5) << shown;
  for (const auto& p : probes) {
    if (p["role"] == "target") continue;
    const int x = int(p["pixel"][0].get<double>()), y = int(p["pixel"][1].get<double>());
    EXPECT_NE(a->at(x, y), b->at(x, y)) << "no mark at " << x << "," << y << " of " << shown;
  }
}

}  // namespace

TEST(ExternalImagesInASet, VtkImagesOfEachViewAlignAndCarryTheQuestionsMarks) {
  const auto dir = setFolder("set_images");
  drawViews(dir, "renders");
  std::ofstream(dir / "set.toml") << setText("renders/{scene}-{view}.png");
  const auto r = runSet(dir / "set.toml", dir / "out");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto manifest = nlohmann::json::parse(readText((dir / "out" / "manifest.json").string()));
  ASSERT_EQ(manifest["styles"].size(), 3u);
  EXPECT_EQ(manifest["styles"][1]["style_sha256"], sha256sum(dir / "styles" / "mine.glsl"));
  EXPECT_EQ(manifest["styles"][2]["images"], "renders/{scene}-{view}.png");
  ASSERT_EQ(manifest["stimuli"].size(), 9u);  // torus: 2 views x 3 styles; spheres: 1 view x 3 styles
  const std::map<std::pair<int, int>, std::string> expected = {{{1, 1}, "renders/torus-v1.png"}, {{1, 2}, "renders/torus-side.png"},
                                                                {{2, 1}, "renders/spheres-v1.png"}};
  std::map<std::pair<int, int>, nlohmann::json> constantQuestion;
  int theirs = 0;
  for (const auto& s : manifest["stimuli"]) {
    const std::pair<int, int> view{s["scene"].get<int>(), s["view"]["index"].get<int>()};
    if (s["style"] == 1) constantQuestion[view] = s["question"];
    if (s["style"] != 3) {
      EXPECT_FALSE(s.contains("source_image"));
      continue;
    }
    ++theirs;
    const auto& source = s["source_image"];
    EXPECT_EQ(source["path"], expected.at(view)) << s;
    EXPECT_EQ(source["sha256"], sha256sum(dir / source["path"].get<std::string>()));  // coreutils, not tlab's SHA-256
    EXPECT_GE(source["iou"].get<double>(), 0.98);
    // tlab's questions of the view, with their ground truth from the geometry, marked over the image.
    EXPECT_EQ(s["question"], constantQuestion.at(view));
    expectMarksOverTheImage(dir / "out" / s["image"].get<std::string>(), dir / source["path"].get<std::string>(), s["question"]["probes"]);
  }
  EXPECT_EQ(theirs, 3);
  const std::string pages = tlab::analysis::pdfText((dir / "out" / "booklet.pdf").string());
  for (const auto& s : manifest["stimuli"]) EXPECT_NE(pages.find("code " + s["booklet_code"].get<std::string>()), std::string::npos) << s["id"];
}

TEST(ExternalImagesInASet, AnImageFromAShiftedCameraIsRefusedWithItsIoUBeforeAnythingIsDrawn) {
  const auto dir = setFolder("set_images_shifted");
  drawViews(dir, "shifted");
  ASSERT_EQ(drawWithVtk("builtin:torus", "128x96", "", dir / "shifted" / "torus-v1.png", "--shift 0.25,0,0"), "");
  std::ofstream(dir / "set.toml") << setText("shifted/{scene}-{view}.png");
  const auto r = runSet(dir / "set.toml", dir / "out");
  std::cout << r.err;
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("set.toml:5: set.styles[2].images: " + (dir / "shifted" / "torus-v1.png").string() + ": IoU "), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("of builtin:torus view v1 (below 0.98)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("likely cause: shifted camera"), std::string::npos) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, std::regex(R"(IoU ([0-9.]+))")));
  EXPECT_LT(std::stod(m[1]), 0.98);
  EXPECT_FALSE(fs::exists(dir / "out" / "booklet.pdf"));
  EXPECT_FALSE(fs::exists(dir / "out" / "manifest.json"));
}
