#include "renderer/gpu/gl_error.hpp"

#include "renderer/gpu/gl.hpp"

namespace tlab::gpu {

namespace {
std::string glErrorName(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    default: return "GL error " + std::to_string(e);
  }
}
}  // namespace

void checkGl(std::string_view what) {
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR) {
    // Drain further queued errors so the next check starts clean.
    while (glGetError() != GL_NO_ERROR) {
    }
    throw GlError(glErrorName(e) + " in " + std::string(what));
  }
}

}  // namespace tlab::gpu
