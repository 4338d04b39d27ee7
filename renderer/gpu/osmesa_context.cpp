// Headless OpenGL 4.5 core through OSMesa (Mesa llvmpipe).
#include "renderer/gpu/gl.hpp"
// glad's header must come first: it guards GL/gl.h, which osmesa.h pulls in.
#include <GL/osmesa.h>

#include <vector>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/gpu_context.hpp"

namespace tlab::gpu {

GpuInfo GpuContext::info() const {
  auto str = [](GLenum e) {
    const auto* s = reinterpret_cast<const char*>(glGetString(e));
    return std::string(s ? s : "");
  };
  return {str(GL_VENDOR), str(GL_RENDERER), str(GL_VERSION), str(GL_SHADING_LANGUAGE_VERSION)};
}

namespace {

GLADapiproc osmesaLoad(const char* name) {
  return reinterpret_cast<GLADapiproc>(OSMesaGetProcAddress(name));
}

class OsmesaContext final : public GpuContext {
 public:
  OsmesaContext() {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx_)
      throw GlError("cannot create a headless OSMesa OpenGL 4.5 core context (is libosmesa6 installed? is MESA_GL_VERSION_OVERRIDE set below 4.5?)");
    // OSMesa needs a default framebuffer to make the context current; we render into our own
    // framebuffer objects, so a 1x1 surface is enough.
    surface_.assign(4, 0);
    if (!OSMesaMakeCurrent(ctx_, surface_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      OSMesaDestroyContext(ctx_);
      throw GlError("cannot make the OSMesa context current");
    }
    if (gladLoadGL(osmesaLoad) == 0) {
      OSMesaDestroyContext(ctx_);
      throw GlError("cannot load OpenGL 4.5 core entry points through OSMesa");
    }
  }
  ~OsmesaContext() override { OSMesaDestroyContext(ctx_); }
  std::string backendName() const override { return "osmesa"; }

 private:
  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> surface_;
};

}  // namespace

std::unique_ptr<GpuContext> createHeadlessContext() { return std::make_unique<OsmesaContext>(); }

}  // namespace tlab::gpu
