// `tlab stimuli` end to end: labelled PNGs, manifest with SHA-256, floor plans, the booklet;
// byte-identical across runs and across --jobs; errors naming the set file's line.
#include <gtest/gtest.h>

#include <set>

#include "analysis/document_text.hpp"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/sha256.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/tlab_version.hpp"

namespace tlab::stimuli {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::readText;
using testing::runCommand;

std::string dataFile(const std::string& name) { return std::string(TLAB_TEST_DATA) + "/stimuli/" + name; }

testing::CommandResult runSet(const std::string& set, const fs::path& out, int jobs) {
  return runCommand(std::string(TLAB_EXE) + " stimuli " + quoted(set) + " -o " + quoted(out.string()) + " --jobs " + std::to_string(jobs));
}

// Every file under `dir` with its bytes, by relative path.
std::map<std::string, std::string> folderBytes(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = readText(e.path().string());
  return files;
}

class StimulusSetCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = testing::freshDir("stimuli_cli");
    first_ = runSet(dataFile("small_set.toml"), root_ / "a", 1);
    second_ = runSet(dataFile("small_set.toml"), root_ / "b", 1);
    parallel_ = runSet(dataFile("small_set.toml"), root_ / "c", 2);
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }
  static inline fs::path root_;
  static inline testing::CommandResult first_, second_, parallel_;
};

TEST_F(StimulusSetCli, WritesLabelledImagesManifestFloorPlanAndBooklet) {
  ASSERT_EQ(first_.exitCode, 0) << first_.err;
  const auto manifest = nlohmann::json::parse(readText((root_ / "a" / "manifest.json").string()));
  // open cylinders: 2 views × 2 styles × 1 question; walkthrough: 1 view × 2 styles unlabelled;
  // nested spheres: 1 view × 2 styles × 1 layer-index question.
  ASSERT_EQ(manifest["stimuli"].size(), 8u);
  // The GL that drew the set (issue #19): backend and renderer strings of the context.
  EXPECT_NE(manifest["gl"]["backend"].get<std::string>(), "");
  EXPECT_NE(manifest["gl"]["renderer"].get<std::string>(), "");
  EXPECT_NE(manifest["gl"]["version"].get<std::string>().find("4."), std::string::npos) << manifest["gl"];
  // And the tlab that drew it, as `tlab version` names it.
  const std::string version = testing::tlabVersionString();
  ASSERT_NE(version, "");
  EXPECT_EQ(manifest["tlab_version"], version);
  for (const auto& s : manifest["stimuli"]) {
    const std::string bytes = readText((root_ / "a" / s["image"].get<std::string>()).string());
    ASSERT_FALSE(bytes.empty());
    EXPECT_EQ(s["sha256"], tlab::core::sha256Hex(std::string_view(bytes)));
    EXPECT_EQ(s["view"]["camera"]["eye"].size(), 3u);
  }
  const auto& labelled = manifest["stimuli"][0];
  ASSERT_TRUE(labelled.contains("question"));
  const auto& probes = labelled["question"]["probes"];
  ASSERT_EQ(probes.size(), 2u);
  EXPECT_EQ(probes[0]["label"], "A");
  EXPECT_EQ(probes[1]["label"], "B");
  for (const auto& p : probes) {
    EXPECT_EQ(p["world"].size(), 3u);
    EXPECT_GT(p["pixel"][0].get<double>(), 0.0);
    EXPECT_LT(p["pixel"][1].get<double>(), 96.0);
  }
  EXPECT_TRUE(labelled["question"]["ground_truth"].is_null());  // "points" has no ground truth
  EXPECT_EQ(manifest["scenes"][1]["floor_plan"], "floor-plans/s02-walkthrough.png");
  EXPECT_TRUE(fs::exists(root_ / "a" / "floor-plans" / "s02-walkthrough.png"));
  // A task's question carries its exact ground truth (the hook to the tasks library).
  const auto& task = manifest["stimuli"][6];
  EXPECT_EQ(task["scene"], 3);
  EXPECT_EQ(task["question"]["ground_truth"]["task"], "layer-index");
  EXPECT_TRUE(task["question"]["ground_truth"].contains("truth"));
  EXPECT_FALSE(task["question"]["probes"].empty());
  const std::string pdf = readText((root_ / "a" / "booklet.pdf").string());
  EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
  // Nothing on a page names a condition: each page shows a neutral code that the manifest maps back.
  const std::string pages = tlab::analysis::pdfText((root_ / "a" / "booklet.pdf").string());
  std::set<std::string> codes;
  for (const auto& item : manifest["stimuli"]) {
    const std::string code = item["booklet_code"];
    EXPECT_EQ(code.size(), 8u);
    codes.insert(code);
    EXPECT_NE(pages.find("code " + code), std::string::npos) << code;
    EXPECT_EQ(pages.find(item["id"].get<std::string>()), std::string::npos) << "the page names " << item["id"];
  }
  EXPECT_EQ(codes.size(), manifest["stimuli"].size());
  for (const char* style : {"constant", "smart", "opaque"}) EXPECT_EQ(pages.find(style), std::string::npos) << style;
}

TEST_F(StimulusSetCli, SameInputsGiveTheSameBytesForAnyNumberOfJobs) {
  ASSERT_EQ(second_.exitCode, 0) << second_.err;
  ASSERT_EQ(parallel_.exitCode, 0) << parallel_.err;
  const auto a = folderBytes(root_ / "a");
  EXPECT_EQ(a.size(), 11u);  // 8 images, manifest, floor plan, booklet
  EXPECT_TRUE(a == folderBytes(root_ / "b"));
  EXPECT_TRUE(a == folderBytes(root_ / "c"));
}

TEST(StimulusSetCliErrors, BadFilesNameTheLine) {
  const auto out = testing::freshDir("stimuli_bad");
  const auto style = runSet(dataFile("bad_style.toml"), out, 1);
  EXPECT_EQ(style.exitCode, 1);
  EXPECT_NE(style.err.find("bad_style.toml:6: set.styles[1]"), std::string::npos) << style.err;
  const auto key = runSet(dataFile("bad_key.toml"), out, 1);
  EXPECT_NE(key.err.find("bad_key.toml:8: scene[0].probes[0].cuont: unknown key"), std::string::npos) << key.err;
  const auto scene = runSet(dataFile("bad_scene.toml"), out, 1);
  EXPECT_NE(scene.err.find("bad_scene.toml:10: scene[1].source: unknown built-in scene 'no-such-scene'"), std::string::npos) << scene.err;
  fs::remove_all(out);
}

}  // namespace
}  // namespace tlab::stimuli
