// End-to-end: `tlab figures` re-draws the seeds' figures; at 48x48 they are the regression set.
// Each figure's SHA-256 must match tests/data/figures/sha256.txt (byte-identical on the Mesa
// llvmpipe this project builds with; the fills and the sort are deterministic). A fix that
// changes a figure on purpose regenerates the list with TLAB_UPDATE_FIGURES=1 and says so.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

#include "core/image.hpp"
#include "core/sha256.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/tlab_version.hpp"

using namespace tlab::testing;
namespace fs = std::filesystem;

namespace {

const std::string kTlab = TLAB_EXE;
const std::string kHashes = std::string(TLAB_TEST_DATA) + "/figures/sha256.txt";

std::map<std::string, std::string> readHashes() {
  std::map<std::string, std::string> hashes;
  std::istringstream in(readText(kHashes));
  std::string hash, file;
  while (in >> hash >> file) hashes[file] = hash;
  return hashes;
}

// The command under a figure's heading in figures.md.
std::string commandOf(const std::string& captions, const std::string& id) {
  const auto heading = captions.find("## " + id + "\n");
  const auto start = captions.find("```sh\n", heading) + 6;
  return captions.substr(start, captions.find('\n', start) - start);
}

}  // namespace

TEST(FiguresCli, EveryFigureMatchesItsHashAndItsCaptionedCommand) {
  const auto dir = freshDir("figures_cli");
  const auto r = runCommand(kTlab + " figures --out " + dir.string() + " --size 48x48 --tile 48");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::map<std::string, std::string> actual;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() == ".png" && name != "figures.png") actual[name] = tlab::core::sha256Hex(readText(entry.path().string()));
  }
  EXPECT_GE(actual.size(), 25u);
  if (std::getenv("TLAB_UPDATE_FIGURES")) {
    std::string text;
    for (const auto& [file, hash] : actual) text += hash + "  " + file + "\n";
    fs::create_directories(fs::path(kHashes).parent_path());
    tlab::core::writeFileAtomically(kHashes, std::vector<std::uint8_t>(text.begin(), text.end()));
    GTEST_SKIP() << "rewrote " << kHashes;
  }
  EXPECT_EQ(actual, readHashes()) << "a figure changed: look at it, then TLAB_UPDATE_FIGURES=1 rewrites " << kHashes;
  // The caption's command, run as printed (in the output folder), writes the same bytes.
  const std::string captions = readText((dir / "figures.md").string());
  for (const char* id : {"diepstraten-fig3a-standard", "iris-fig10a-peeled"}) {
    const std::string command = commandOf(captions, id);
    ASSERT_EQ(command.rfind("tlab render ", 0), 0u) << command;
    const auto again = runCommand("cd " + dir.string() + " && " + kTlab + command.substr(4) + " >/dev/null");
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(tlab::core::sha256Hex(readText((dir / (std::string(id) + ".png")).string())), actual[std::string(id) + ".png"])
        << command;
  }
  EXPECT_NE(captions.find("Carnecky et al. 2013 (seed 000), Fig. 9 (a)"), std::string::npos);
  const std::string version = tlabVersionString();
  ASSERT_NE(version, "");
  EXPECT_NE(captions.find("Drawn by tlab " + version + " on "), std::string::npos) << captions.substr(0, 400);
}

TEST(FiguresCli, AnUnknownSelectionIsAOneLineError) {
  const auto r = runCommand(kTlab + " figures --out " + freshDir("figures_none").string() + " --only nothing-like-this");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("--only 'nothing-like-this' matches no figure"), std::string::npos) << r.err;
}
