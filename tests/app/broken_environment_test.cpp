// Broken environments, end to end through `tlab render`: no display for --window, no OpenGL 4.5
// context from OSMesa, and an illustration buffer larger than the GPU allows (a shader that
// fails to compile: tests/renderer/shader_errors_gl_test.cpp). Each is one line "tlab: error: ...", exit 1, and no output file (nor a
// temporary one) left in the output folder. Mesa's MESA_GL_VERSION_OVERRIDE=3.3 makes the 4.5
// core context impossible.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/run_command.hpp"

using namespace tlab::testing;

namespace {

const std::string kTlab = TLAB_EXE;

// Runs `tlab render` with `env` into an empty folder; expects one error line containing `part`
// and an empty folder afterwards.
void expectCleanFailure(const std::string& name, const std::string& env, const std::string& args, const std::string& part) {
  const auto dir = freshDir("broken_" + name);
  const std::string out = (dir / "out.png").string();
  const auto r = runCommand("env " + env + " " + kTlab + " render " + args + " -o " + tlab::testing::quoted(out) + " --stats-json " +
                            tlab::testing::quoted((dir / "stats.json").string()));
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_EQ(r.err.rfind("tlab: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "output left behind in " << dir;
}

}  // namespace

TEST(BrokenEnvironment, NoDisplayForAWindowSuggestsHeadless) {
  expectCleanFailure("no_display", "-u DISPLAY -u WAYLAND_DISPLAY", "builtin:sphere --window", "render headless without --window");
}

TEST(BrokenEnvironment, NoOpenGl45ContextFromOsmesa) {
  expectCleanFailure("osmesa", "MESA_GL_VERSION_OVERRIDE=3.3", "builtin:sphere --size 32x32",
                     "cannot create a headless OSMesa OpenGL 4.5 core context");
}

TEST(BrokenEnvironment, IllustrationBufferOverTheLimitGivesTheNumbers) {
  expectCleanFailure("pool", "", "builtin:sphere --size 8192x8192", "the illustration buffer needs 67108864 fragments x ");
}

TEST(BrokenEnvironment, OutputFilesAreWrittenAllOrNone) {
  const auto dir = freshDir("broken_outputs");
  const std::string out = (dir / "out.png").string();
  const auto r = runCommand(kTlab + " render builtin:sphere --size 32x32 -o " + tlab::testing::quoted(out) + " --stats-json " +
                            tlab::testing::quoted((dir / "missing-folder" / "stats.json").string()));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("stats.json: cannot write"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "out.png was left although stats.json failed";
}
