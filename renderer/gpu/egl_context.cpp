// Headless OpenGL 4.5 core through EGL, loaded at run time (dlopen of libEGL.so.1): the device
// platform (EGL_EXT_platform_device: a GPU without a display, or Mesa's software device) or
// Mesa's surfaceless platform (EGL_MESA_platform_surfaceless). No surface: tlab renders into its
// own framebuffer objects, so the context is made current with EGL_NO_SURFACE
// (EGL_KHR_surfaceless_context).
#include "renderer/gpu/gl.hpp"
// glad's header first; EGL's own headers declare no GL entry points.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <mutex>

#include "renderer/gpu/egl_context.hpp"
#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/shared_library.hpp"

namespace tlab::gpu {

namespace {

// libEGL's entry points, loaded once per process (TLAB_LIBEGL names another library file).
struct EglApi {
  SharedLibrary lib;
  PFNEGLGETPROCADDRESSPROC getProcAddress;
  PFNEGLQUERYSTRINGPROC queryString;
  PFNEGLINITIALIZEPROC initialize;
  PFNEGLTERMINATEPROC terminate;
  PFNEGLBINDAPIPROC bindApi;
  PFNEGLCHOOSECONFIGPROC chooseConfig;
  PFNEGLCREATECONTEXTPROC createContext;
  PFNEGLDESTROYCONTEXTPROC destroyContext;
  PFNEGLMAKECURRENTPROC makeCurrent;
  PFNEGLGETERRORPROC getError;
  PFNEGLRELEASETHREADPROC releaseThread;
  PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay = nullptr;
  PFNEGLQUERYDEVICESEXTPROC queryDevices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC queryDeviceString = nullptr;

  static std::vector<std::string> names() {
    const char* env = std::getenv("TLAB_LIBEGL");
    if (env && *env) return {env};
    return {"libEGL.so.1", "libEGL.so"};
  }
  EglApi()
      : lib(names(), "install the GPU driver's EGL (Debian: libegl1 and libegl-mesa0) or use --gl osmesa"),
        getProcAddress(lib.function<PFNEGLGETPROCADDRESSPROC>("eglGetProcAddress")),
        queryString(lib.function<PFNEGLQUERYSTRINGPROC>("eglQueryString")),
        initialize(lib.function<PFNEGLINITIALIZEPROC>("eglInitialize")),
        terminate(lib.function<PFNEGLTERMINATEPROC>("eglTerminate")),
        bindApi(lib.function<PFNEGLBINDAPIPROC>("eglBindAPI")),
        chooseConfig(lib.function<PFNEGLCHOOSECONFIGPROC>("eglChooseConfig")),
        createContext(lib.function<PFNEGLCREATECONTEXTPROC>("eglCreateContext")),
        destroyContext(lib.function<PFNEGLDESTROYCONTEXTPROC>("eglDestroyContext")),
        makeCurrent(lib.function<PFNEGLMAKECURRENTPROC>("eglMakeCurrent")),
        getError(lib.function<PFNEGLGETERRORPROC>("eglGetError")),
        releaseThread(lib.function<PFNEGLRELEASETHREADPROC>("eglReleaseThread")) {
    getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(getProcAddress("eglGetPlatformDisplayEXT"));
    queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(getProcAddress("eglQueryDevicesEXT"));
    queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(getProcAddress("eglQueryDeviceStringEXT"));
  }
};

std::mutex eglMutex;  // guards the API's creation and the display reference counts

EglApi& egl() {
  static EglApi api;  // a failed load throws and is retried by the next call
  return api;
}

// EGL displays are per process; worker threads share one. It is terminated with its last context.
std::vector<std::pair<EGLDisplay, int>>& displayUses() {
  static std::vector<std::pair<EGLDisplay, int>> uses;
  return uses;
}

std::string hex(EGLint e) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%04X", static_cast<unsigned>(e));
  return b;
}

bool hasExtension(const char* list, const std::string& name) {
  if (!list) return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(" " + name + " ") != std::string::npos;
}

GLADapiproc eglLoad(const char* name) { return reinterpret_cast<GLADapiproc>(egl().getProcAddress(name)); }

}  // namespace

std::vector<EglDevice> listEglDevices() {
  const std::lock_guard lock(eglMutex);
  EglApi& api = egl();
  if (!api.queryDevices || !api.getPlatformDisplay) return {};
  EGLint n = 0;
  if (!api.queryDevices(0, nullptr, &n) || n <= 0) return {};
  std::vector<EGLDeviceEXT> handles(static_cast<std::size_t>(n));
  api.queryDevices(n, handles.data(), &n);
  std::vector<EglDevice> out;
  for (EGLint i = 0; i < n; ++i) {
    const char* ext = api.queryDeviceString ? api.queryDeviceString(handles[i], EGL_EXTENSIONS) : nullptr;
    const char* file = hasExtension(ext, "EGL_EXT_device_drm") ? api.queryDeviceString(handles[i], EGL_DRM_DEVICE_FILE_EXT) : nullptr;
    EglDevice d;
    d.index = i;
    d.handle = handles[i];
    d.software = hasExtension(ext, "EGL_MESA_device_software");
    d.name = file ? file : d.software ? "software" : "device " + std::to_string(i);
    out.push_back(d);
  }
  return out;
}

EglContext::EglContext(void* device, const std::string& description) : description_(description) {
  const std::lock_guard lock(eglMutex);
  EglApi& api = egl();
  const char* clientExtensions = api.queryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  const bool wantDevice = device != nullptr;
  const char* needed = wantDevice ? "EGL_EXT_platform_device" : "EGL_MESA_platform_surfaceless";
  if (!api.getPlatformDisplay || !hasExtension(clientExtensions, needed))
    throw GlError(api.lib.name() + " lacks " + needed);
  display_ = api.getPlatformDisplay(wantDevice ? EGL_PLATFORM_DEVICE_EXT : EGL_PLATFORM_SURFACELESS_MESA,
                                    wantDevice ? device : EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (display_ == EGL_NO_DISPLAY || !api.initialize(display_, &major, &minor))
    throw GlError("no EGL display on " + description + " (EGL error " + hex(api.getError()) + ")");
  auto& uses = displayUses();
  auto use = std::find_if(uses.begin(), uses.end(), [&](const auto& u) { return u.first == display_; });
  if (use == uses.end()) uses.emplace_back(display_, 1);
  else ++use->second;
  try {
    createAndBind();
  } catch (...) {
    release();
    throw;
  }
}

void EglContext::createAndBind() {
  EglApi& api = egl();
  if (!api.bindApi(EGL_OPENGL_API)) throw GlError("EGL on " + description_ + " has no desktop OpenGL");
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!hasExtension(api.queryString(display_, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
    const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
    EGLint count = 0;
    if (!api.chooseConfig(display_, attribs, &config, 1, &count) || count < 1)
      throw GlError("EGL on " + description_ + " offers no OpenGL configuration");
  }
  const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  context_ = api.createContext(display_, config, EGL_NO_CONTEXT, contextAttribs);
  if (context_ == EGL_NO_CONTEXT)
    throw GlError("EGL on " + description_ + " gives no OpenGL 4.5 core context (EGL error " + hex(api.getError()) + ")");
  if (!api.makeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
    throw GlError("cannot make the EGL context current on " + description_ + " (EGL error " + hex(api.getError()) + ")");
  requireGl45(gladLoadGL(eglLoad), "EGL on " + description_);
}

void EglContext::release() {
  EglApi& api = egl();
  api.makeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_ != EGL_NO_CONTEXT) api.destroyContext(display_, context_);
  auto& uses = displayUses();
  auto use = std::find_if(uses.begin(), uses.end(), [&](const auto& u) { return u.first == display_; });
  if (use != uses.end() && --use->second == 0) {
    api.terminate(display_);
    uses.erase(use);
  }
  api.releaseThread();
}

EglContext::~EglContext() {
  const std::lock_guard lock(eglMutex);
  release();
}

}  // namespace tlab::gpu
