// End to end through `tlab render`: the headless GL backends (--gl / TLAB_GL). Mesa's EGL
// (llvmpipe, surfaceless and the software device) and OSMesa (llvmpipe) give byte-identical
// pictures on this machine; the one chosen is named in --stats-json; every way the choice can
// fail is one error line naming what was tried and the remedy, exit 1, nothing written.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"

using namespace tlab::testing;

namespace {

const std::string kTlab = TLAB_EXE;

// Renders builtin:SCENE in `style` through `gl` (an --gl value) and returns the PNG's bytes and
// the stats' "gpu" object.
std::pair<std::string, nlohmann::json> render(const std::string& scene, const std::string& style, const std::string& gl,
                                              const std::string& env = "") {
  const auto dir = freshDir("gl_" + style + "_" + gl.substr(0, 3));
  const std::string png = (dir / "out.png").string(), stats = (dir / "stats.json").string();
  const auto r = runCommand("env " + env + " " + kTlab + " render " + scene + " --style " + style + " --size 96x72 " +
                            (gl.empty() ? "" : "--gl " + gl) + " -o " + quoted(png) + " --stats-json " + quoted(stats));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  if (r.exitCode != 0) return {};
  return {readText(png), nlohmann::json::parse(readText(stats))["gpu"]};
}

void expectCleanFailure(const std::string& env, const std::string& gl, const std::vector<std::string>& parts) {
  const auto dir = freshDir("gl_fail");
  const auto r = runCommand("env " + env + " " + kTlab + " render builtin:sphere --size 16x16 " + gl + " -o " +
                            quoted((dir / "out.png").string()));
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_EQ(r.err.rfind("tlab: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (const auto& part : parts) EXPECT_NE(r.err.find(part), std::string::npos) << "'" << part << "' not in " << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace

TEST(GlBackends, EglAndOsmesaDrawByteIdenticalPictures) {
  const std::string scene = "builtin:nested-spheres?n=3";
  for (const char* style : {"opaque", "constant", "unsorted", "smart", "angle", "normal-variation", "iris", "view-dependent",
                            "dynamic", "curvature"}) {
    const auto [osmesa, osmesaGpu] = render(scene, style, "osmesa");
    const auto [egl, eglGpu] = render(scene, style, "egl");
    const auto [surfaceless, surfacelessGpu] = render(scene, style, "", "TLAB_GL=auto");
    ASSERT_FALSE(osmesa.empty());
    EXPECT_TRUE(osmesa == egl) << style << " differs between OSMesa and EGL";
    EXPECT_TRUE(osmesa == surfaceless) << style << " differs between OSMesa and auto";
    EXPECT_EQ(osmesaGpu["backend"], "osmesa");
    EXPECT_EQ(std::string(eglGpu["backend"]).rfind("egl ", 0), 0u) << eglGpu;
    for (const auto& gpu : {osmesaGpu, eglGpu, surfacelessGpu}) {
      EXPECT_NE(std::string(gpu["renderer"]), "");
      EXPECT_NE(std::string(gpu["version"]).find("4."), std::string::npos) << gpu;
    }
  }
}

TEST(GlBackends, TheEnvironmentVariableChoosesWhenTheOptionIsAbsent) {
  EXPECT_EQ(render("builtin:sphere", "constant", "", "TLAB_GL=osmesa").second["backend"], "osmesa");
  EXPECT_EQ(render("builtin:sphere", "constant", "osmesa", "TLAB_GL=egl").second["backend"], "osmesa");  // --gl wins
}

TEST(GlBackends, BadChoicesAreOneLineWithTheRemedy) {
  expectCleanFailure("", "--gl egl:9", {"EGL device 9 is out of range", "pick one of them with --gl egl:N"});
  expectCleanFailure("", "--gl vulkan", {"--gl", "'vulkan' is not auto, egl, egl:N"});
  expectCleanFailure("TLAB_GL=gles", "", {"TLAB_GL: 'gles'"});
  // glvnd finds no EGL vendor: no display on any platform.
  expectCleanFailure("__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json", "--gl egl",
                     {"--gl egl: no EGL OpenGL 4.5 context", "use --gl osmesa"});
  // A context below 4.5 (Mesa's override), through EGL and through everything auto tries.
  expectCleanFailure("MESA_GL_VERSION_OVERRIDE=3.3", "--gl egl", {"gives no OpenGL 4.5 core context", "use --gl osmesa"});
  expectCleanFailure("MESA_GL_VERSION_OVERRIDE=3.3", "", {"no headless OpenGL 4.5 core context (tried: ", "OSMesa"});
  // The libraries are opened at run time: a missing one is named with the package to install.
  expectCleanFailure("TLAB_LIBEGL=/nonexistent/libEGL.so.1", "--gl egl", {"cannot load /nonexistent/libEGL.so.1", "libegl1"});
  expectCleanFailure("TLAB_LIBOSMESA=/nonexistent/libOSMesa.so.8", "--gl osmesa",
                     {"cannot load /nonexistent/libOSMesa.so.8", "libosmesa6", "use --gl egl"});
}

TEST(GlBackends, AutoFallsBackToOsmesaWithoutLibEgl) {
  EXPECT_EQ(render("builtin:sphere", "constant", "auto", "TLAB_LIBEGL=/nonexistent/libEGL.so.1").second["backend"], "osmesa");
}
