#pragma once
// A headless OpenGL 4.5 core context through EGL (renderer/gpu/egl_context.cpp).
#include <string>
#include <vector>

#include "renderer/gpu/gpu_context.hpp"

namespace tlab::gpu {

// One device of EGL's device platform (EGL_EXT_device_enumeration).
struct EglDevice {
  int index = 0;
  void* handle = nullptr;  // EGLDeviceEXT
  bool software = false;   // EGL_MESA_device_software: llvmpipe, not a GPU
  std::string name;        // the DRM device file, or "software"
};

// The devices libEGL lists; empty without the device extensions. Throws GlError when libEGL
// cannot be loaded.
std::vector<EglDevice> listEglDevices();

class EglContext final : public GpuContext {
 public:
  // `device` (an EGLDeviceEXT) on the device platform, or nullptr for Mesa's surfaceless
  // platform. `description` names it in errors and in backendName(). Throws GlError.
  EglContext(void* device, const std::string& description);
  ~EglContext() override;
  std::string backendName() const override { return "egl " + description_; }

 private:
  void createAndBind();
  void release();

  std::string description_;
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
};

}  // namespace tlab::gpu
