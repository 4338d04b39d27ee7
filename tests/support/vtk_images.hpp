#pragma once
// Pictures from a real other renderer for the tests of images from another renderer (issue #28):
// `tlab scene export` writes the scene and tlab's camera as glTF, and VTK (Debian's python3-vtk9,
// scripts/render_with_vtk.py, under xvfb-run) draws it from that camera.
#include <filesystem>
#include <string>

#include "tests/support/run_command.hpp"

namespace tlab::testing {

// Exports `scene` for `size` (and `camera`, when given) to GLB and draws it with VTK into `png`;
// `extra`: render_with_vtk.py options (--shift DX,DY,DZ, --flip). The failing step's output, or "".
inline std::string drawWithVtk(const std::string& scene, const std::string& size, const std::string& camera,
                               const std::filesystem::path& png, const std::string& extra = "") {
  std::filesystem::create_directories(png.parent_path());
  const std::string glb = png.string() + ".glb";
  const auto exported = runCommand(std::string(TLAB_EXE) + " scene export " + quoted(scene) + " --size " + size +
                                   (camera.empty() ? "" : " --camera " + quoted(camera)) + " -o " + quoted(glb));
  if (exported.exitCode != 0) return "tlab scene export: " + exported.err;
  const auto drawn = runCommand("xvfb-run -a -s '-screen 0 640x480x24' /usr/bin/python3 " + std::string(TLAB_SOURCE_DIR) +
                                "/scripts/render_with_vtk.py " + quoted(glb) + " " + quoted(png.string()) + " " + extra);
  std::filesystem::remove(glb);
  if (drawn.exitCode != 0)
    return "VTK could not draw the exported scene (scripts/setup.sh installs python3-vtk9 and xvfb): " + drawn.out + drawn.err;
  return "";
}

}  // namespace tlab::testing
