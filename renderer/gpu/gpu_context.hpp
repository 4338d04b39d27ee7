#pragma once
// GpuContext hides how we got an OpenGL 4.5 core context: headless through OSMesa (llvmpipe; the
// default, used by tests and CI) or a GLFW window. Nothing else knows which one runs. The context
// is the only global GL state owner: create one per process/thread and keep it alive while any GL
// object lives.
#include <memory>
#include <string>

namespace tlab::gpu {

struct GpuInfo {
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
  GpuInfo info() const;

  // Window contexts show an RGBA8 image (row 0 = top) and keep it up until the window closes.
  virtual bool isWindow() const { return false; }
};

// Headless OSMesa core-profile 4.5 context. Throws GlError when it cannot be created.
std::unique_ptr<GpuContext> createHeadlessContext();

// A visible GLFW window with a 4.5 core context. Throws with a one-line message suggesting the
// headless mode when no display is available.
class WindowContext;
std::unique_ptr<WindowContext> createWindowContext(int width, int height, const std::string& title);

}  // namespace tlab::gpu
