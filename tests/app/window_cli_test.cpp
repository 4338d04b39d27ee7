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
  const auto windowPng = (dir / "window.png").string(), headlessPng = (dir / "headless.png").string();
  const auto displayFile = (dir / "display").string(), errFile = (dir / "err.txt").string();
  const std::string args = " render builtin:open-cylinders --size 160x120 --style constant -o ";
  // Xvfb picks a free display itself (-displayfd); tlab runs on it in the background; we wait for
  // its window, press Escape (again until tlab has gone), and a watchdog ends tlab if the window never shows up.
  const std::string script =
      "Xvfb -displayfd 3 -screen 0 640x480x24 3>" + displayFile + " >/dev/null 2>&1 & XPID=$!; "
      "for i in $(seq 100); do [ -s " + displayFile + " ] && break; sleep 0.1; done; "
      "export DISPLAY=:$(cat " + displayFile + "); "
      + kTlab + args + windowPng + " --window >/dev/null 2>" + errFile + " & TPID=$!; "
      "(sleep 60; kill $TPID) >/dev/null 2>&1 & WATCHDOG=$!; "
      "WID=$(timeout 30 xdotool search --sync --name tlab.render | head -1); "
      // Escape until tlab is gone: a key sent before the window takes input is lost (seen under load
      // with another Xvfb test running beside this one).
      "for i in $(seq 100); do kill -0 $TPID 2>/dev/null || break; xdotool key --window \"$WID\" Escape 2>/dev/null; sleep 0.2; done; "
      "wait $TPID; RC=$?; kill $WATCHDOG $XPID 2>/dev/null; echo \"window=$WID rc=$RC\"";
  const auto r = runCommand("bash -c " + quoted(script));
  EXPECT_NE(r.out.find("rc=0"), std::string::npos) << r.out << readText(errFile);
  EXPECT_EQ(r.out.find("window= "), std::string::npos) << "no window appeared: " << r.out;
  ASSERT_EQ(runCommand(kTlab + args + headlessPng).exitCode, 0);
  EXPECT_TRUE(readText(windowPng) == readText(headlessPng)) << "the window's image differs from the headless one";
}
