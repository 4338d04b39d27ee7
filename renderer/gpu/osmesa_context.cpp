// Headless OpenGL 4.5 core through OSMesa (Mesa llvmpipe), loaded at run time (dlopen of
// libOSMesa.so.8; TLAB_LIBOSMESA names another file), so a bundle without Mesa still runs on EGL.
#include "renderer/gpu/osmesa_context.hpp"

#include "renderer/gpu/gl.hpp"
// glad's header must come first: it guards GL/gl.h, which osmesa.h pulls in.
#include <GL/osmesa.h>

#include <cstdlib>
#include <mutex>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/shared_library.hpp"

namespace tlab::gpu {

namespace {

struct OsmesaApi {
  SharedLibrary lib;
  decltype(&OSMesaCreateContextAttribs) createContext;
  decltype(&OSMesaMakeCurrent) makeCurrent;
  decltype(&OSMesaDestroyContext) destroyContext;
  decltype(&OSMesaGetProcAddress) getProcAddress;

  static std::vector<std::string> names() {
    const char* env = std::getenv("TLAB_LIBOSMESA");
    if (env && *env) return {env};
    return {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"};
  }
  OsmesaApi()
      : lib(names(), "install Mesa's OSMesa (Debian: libosmesa6) or use --gl egl"),
        createContext(lib.function<decltype(createContext)>("OSMesaCreateContextAttribs")),
        makeCurrent(lib.function<decltype(makeCurrent)>("OSMesaMakeCurrent")),
        destroyContext(lib.function<decltype(destroyContext)>("OSMesaDestroyContext")),
        getProcAddress(lib.function<decltype(getProcAddress)>("OSMesaGetProcAddress")) {}
};

OsmesaApi& osmesa() {
  static std::mutex m;
  const std::lock_guard lock(m);
  static OsmesaApi api;  // a failed load throws and is retried by the next call
  return api;
}

GLADapiproc osmesaLoad(const char* name) { return reinterpret_cast<GLADapiproc>(osmesa().getProcAddress(name)); }

class OsmesaContext final : public GpuContext {
 public:
  OsmesaContext() : api_(osmesa()) {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    ctx_ = api_.createContext(attribs, nullptr);
    if (!ctx_)
      throw GlError("cannot create a headless OSMesa OpenGL 4.5 core context (is MESA_GL_VERSION_OVERRIDE set below 4.5?)");
    // OSMesa needs a default framebuffer to make the context current; we render into our own
    // framebuffer objects, so a 1x1 surface is enough.
    surface_.assign(4, 0);
    try {
      if (!api_.makeCurrent(ctx_, surface_.data(), GL_UNSIGNED_BYTE, 1, 1)) throw GlError("cannot make the OSMesa context current");
      requireGl45(gladLoadGL(osmesaLoad), "OSMesa");
    } catch (...) {
      api_.destroyContext(ctx_);
      throw;
    }
  }
  ~OsmesaContext() override { api_.destroyContext(ctx_); }
  std::string backendName() const override { return "osmesa"; }

 private:
  OsmesaApi& api_;
  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> surface_;
};

}  // namespace

std::unique_ptr<GpuContext> createOsmesaContext() { return std::make_unique<OsmesaContext>(); }

}  // namespace tlab::gpu
