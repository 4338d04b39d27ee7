#pragma once
// GpuContext hides how we got an OpenGL 4.5 core context: headless through EGL (a GPU's device
// platform or Mesa's surfaceless platform) or OSMesa (llvmpipe), or a GLFW window. Nothing else
// knows which one runs. The context is the only global GL state owner: create one per
// process/thread and keep it alive while any GL object lives.
#include <memory>
#include <string>

namespace tlab::gpu {

// What a context runs on: recorded with every picture (--stats-json, stimulus manifests, study
// sessions) so a result names the GL that made it.
struct GpuInfo {
  std::string backend;  // "egl device /dev/dri/renderD128", "egl surfaceless", "osmesa", "glfw"
  std::string vendor;
  std::string renderer;
  std::string version;
  std::string glslVersion;
};

class GpuContext {
 public:
  virtual ~GpuContext() = default;
  GpuContext() = default;
  GpuContext(const GpuContext&) = delete;
  GpuContext& operator=(const GpuContext&) = delete;

  virtual std::string backendName() const = 0;
  // The context's backend and GL strings (the context must be current on this thread).
  GpuInfo info() const;

  // Window contexts show an RGBA8 image (row 0 = top) and keep it up until the window closes.
  virtual bool isWindow() const { return false; }
};

// A headless core-profile 4.5 context as --gl / TLAB_GL choose (renderer/gpu/gl_backend.hpp).
// Throws GlError with one line naming what was tried and the remedy.
std::unique_ptr<GpuContext> createHeadlessContext();

// Throws GlError unless glad's loaded version `gladVersion` is at least 4.5; `what` names the
// context in the message.
void requireGl45(int gladVersion, const std::string& what);

// A visible GLFW window with a 4.5 core context. Throws with a one-line message suggesting the
// headless mode when no display is available.
class WindowContext;
std::unique_ptr<WindowContext> createWindowContext(int width, int height, const std::string& title);

}  // namespace tlab::gpu
