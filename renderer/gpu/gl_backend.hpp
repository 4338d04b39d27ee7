#pragma once
// Which headless OpenGL a process uses: `--gl auto|egl|egl:N|osmesa` or the TLAB_GL variable.
//  auto   — an EGL device that is a GPU (EGL_EXT_platform_device), else Mesa's surfaceless EGL
//           platform (llvmpipe), else OSMesa: the first that gives a 4.5 core context.
//  egl    — EGL only: the first EGL device, else Mesa's surfaceless platform.
//  egl:N  — EGL device N of the device platform (an index out of range lists the devices).
//  osmesa — Mesa's off-screen library (llvmpipe on the CPU).
// The choice is process-wide state of the GL context owner (set once, by the command line).
#include <string>

namespace tlab::gpu {

enum class GlBackend { Auto, Egl, Osmesa };

struct GlChoice {
  GlBackend backend = GlBackend::Auto;
  int eglDevice = -1;  // egl:N; -1 = any
};

// Parses "auto", "egl", "egl:N" or "osmesa"; throws std::invalid_argument naming `where`.
GlChoice parseGlChoice(const std::string& text, const std::string& where);
std::string glChoiceName(const GlChoice& choice);

// The command line's --gl; without it, TLAB_GL; without that, auto.
void setGlChoice(const GlChoice& choice);
GlChoice glChoice();

}  // namespace tlab::gpu
