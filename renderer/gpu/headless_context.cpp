// createHeadlessContext: the policy of renderer/gpu/gl_backend.hpp. `auto` walks EGL on a GPU,
// Mesa's surfaceless EGL, then OSMesa, and keeps the reason each one failed for the error line.
#include "renderer/gpu/gl.hpp"

#include "renderer/gpu/egl_context.hpp"
#include "renderer/gpu/gl_backend.hpp"
#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/gl_objects.hpp"
#include "renderer/gpu/osmesa_context.hpp"

namespace tlab::gpu {

GpuInfo GpuContext::info() const {
  auto str = [](GLenum e) {
    const auto* s = reinterpret_cast<const char*>(glGetString(e));
    return std::string(s ? s : "");
  };
  return {backendName(), str(GL_VENDOR), str(GL_RENDERER), str(GL_VERSION), str(GL_SHADING_LANGUAGE_VERSION)};
}

void requireGl45(int gladVersion, const std::string& what) {
  if (gladVersion == 0) throw GlError("cannot load OpenGL entry points through " + what);
  const int major = GLAD_VERSION_MAJOR(gladVersion), minor = GLAD_VERSION_MINOR(gladVersion);
  if (major < 4 || (major == 4 && minor < 5))
    throw GlError(what + " gives OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
                  "; tlab needs 4.5 core (update the driver, or unset MESA_GL_VERSION_OVERRIDE)");
}

namespace {

// EGL device N, or an error listing the devices there are.
std::unique_ptr<GpuContext> eglDevice(int index) {
  const auto devices = listEglDevices();
  if (index >= static_cast<int>(devices.size())) {
    std::string list;
    for (const auto& d : devices) list += (list.empty() ? "" : ", ") + std::to_string(d.index) + ": " + d.name;
    throw GlError("EGL device " + std::to_string(index) + " is out of range: libEGL lists " + std::to_string(devices.size()) +
                  " device(s)" + (list.empty() ? "" : " (" + list + ")") + "; pick one of them with --gl egl:N or use --gl egl");
  }
  return std::make_unique<EglContext>(devices[index].handle, "device " + devices[index].name);
}

// The first EGL device (a GPU only when `gpuOnly`) that gives a context; its failures go to `tried`.
std::unique_ptr<GpuContext> firstEglDevice(bool gpuOnly, std::string& tried) {
  for (const auto& d : listEglDevices()) {
    if (gpuOnly && d.software) continue;
    try {
      return std::make_unique<EglContext>(d.handle, "device " + d.name);
    } catch (const GlError& e) {
      tried += std::string(tried.empty() ? "" : "; ") + e.what();
    }
  }
  if (tried.empty()) tried = gpuOnly ? "no EGL device is a GPU" : "libEGL lists no EGL device";
  return nullptr;
}

template <typename Make>
std::unique_ptr<GpuContext> attempt(Make make, std::string& tried) {
  try {
    return make();
  } catch (const GlError& e) {
    tried += std::string(tried.empty() ? "" : "; ") + e.what();
    return nullptr;
  }
}

// Whether libEGL loads (its failure is one reason, not one per platform).
bool eglLoads(std::string& tried) {
  try {
    listEglDevices();
    return true;
  } catch (const GlError& e) {
    tried += std::string(tried.empty() ? "" : "; ") + e.what();
    return false;
  }
}

std::unique_ptr<GpuContext> anyEgl(bool gpuOnly, std::string& tried) {
  if (!eglLoads(tried)) return nullptr;
  auto c = attempt([&] { return firstEglDevice(gpuOnly, tried); }, tried);
  if (!c) c = attempt([] { return std::make_unique<EglContext>(nullptr, "surfaceless"); }, tried);
  return c;
}

}  // namespace

std::unique_ptr<GpuContext> createHeadlessContext() {
  const GlChoice choice = glChoice();
  hostPassesSetting();  // a wrong TLAB_HOST_PASSES is one line before any work
  drawRunsSetting();    // and a wrong TLAB_DRAW_RUNS
  if (choice.backend == GlBackend::Osmesa) return createOsmesaContext();
  if (choice.backend == GlBackend::Egl && choice.eglDevice >= 0) return eglDevice(choice.eglDevice);
  std::string tried;
  if (choice.backend == GlBackend::Egl) {
    if (auto c = anyEgl(false, tried)) return c;
    throw GlError("--gl egl: no EGL OpenGL 4.5 context (tried: " + tried +
                  ") - install the GPU driver's libEGL, or use --gl osmesa");
  }
  if (auto c = anyEgl(true, tried)) return c;
  if (auto c = attempt(createOsmesaContext, tried)) return c;
  throw GlError("no headless OpenGL 4.5 core context (tried: " + tried +
                ") - install a GPU driver's libEGL or Mesa (libegl-mesa0, libosmesa6)");
}

}  // namespace tlab::gpu
