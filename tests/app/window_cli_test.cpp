// `tlab render --window` in a real GLFW window under Xvfb: the window appears, Escape closes it,
// and the picture equals the headless one. Without a display, one clear line and exit 1.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "tests/support/run_command.hpp"

using namespace tlab::testing;

namespace {
const std::string kTlab = TLAB_EXE;
bool haveTool(const std::string& name) { return runCommand("command -v " + name).exitCode == 0; }
}  // namespace

TEST(WindowCli, WithoutADisplaySuggestsHeadless) {
  const auto dir = freshDir("window_nodisplay");
  const auto r = runCommand("env -u DISPLAY -u WAYLAND_DISPLAY " + kTlab + " render builtin:sphere --window -o " +
                            (dir / "a.png").string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("without --window"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(WindowCli, ShowsTheImageInAGlfwWindowUnderXvfb) {
  if (!haveTool("Xvfb") || !haveTool("xdotool"))
    GTEST_SKIP() << "needs Xvfb and xdotool (scripts/setup.sh installs both)";
  const auto dir = freshDir("window_xvfb");
  const std::string display = ":" + std::to_string(90 + ::getpid() % 100);
  const auto windowPng = (dir / "window.png").string(), headlessPng = (dir / "headless.png").string();
  const std::string args = " render builtin:open-cylinders --size 160x120 --style constant -o ";
  // Xvfb in the background; tlab in the background on it; wait for the window; press Escape.
  const std::string script =
      "Xvfb " + display + " -screen 0 640x480x24 >/dev/null 2>&1 & XPID=$!; sleep 1; "
      "DISPLAY=" + display + " " + kTlab + args + windowPng + " --window >/dev/null 2>" + (dir / "err.txt").string() + " & TPID=$!; "
      "WID=$(DISPLAY=" + display + " timeout 20 xdotool search --sync --name tlab.render | head -1); "
      "DISPLAY=" + display + " xdotool key --window \"$WID\" Escape 2>/dev/null; "
      "wait $TPID; RC=$?; kill $XPID; echo \"window=$WID rc=$RC\"";
  const auto r = runCommand("bash -c " + quoted(script));
  EXPECT_NE(r.out.find("rc=0"), std::string::npos) << r.out << readText((dir / "err.txt").string());
  EXPECT_EQ(r.out.find("window= "), std::string::npos) << "no window appeared: " << r.out;
  ASSERT_EQ(runCommand(kTlab + args + headlessPng).exitCode, 0);
  EXPECT_TRUE(readText(windowPng) == readText(headlessPng)) << "the window's image differs from the headless one";
}
