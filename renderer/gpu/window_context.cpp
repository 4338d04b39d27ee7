#include "renderer/gpu/window_context.hpp"

#include "renderer/gpu/gl.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <string>

#include "renderer/gpu/gl_error.hpp"
#include "renderer/gpu/gl_objects.hpp"

namespace tlab::gpu {

WindowContext::WindowContext(int width, int height, const std::string& title) {
  if (!glfwInit()) {
    throw GlError("no display for a window (GLFW could not initialise; is DISPLAY set?) - render headless without --window");
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw GlError("cannot open a window with an OpenGL 4.5 core context - render headless without --window");
  }
  glfwMakeContextCurrent(window_);
  if (gladLoadGL(glfwGetProcAddress) == 0) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw GlError("cannot load OpenGL 4.5 core entry points through GLFW");
  }
}

WindowContext::~WindowContext() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool WindowContext::shouldClose() const { return glfwWindowShouldClose(window_) != 0; }

void WindowContext::present(const unsigned char* rgba, int width, int height) {
  Texture tex = makeTexture(GL_TEXTURE_2D);
  glTextureStorage2D(tex.id(), 1, GL_RGBA8, width, height);
  glTextureSubImage2D(tex.id(), 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  Framebuffer fbo = makeFramebuffer();
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, tex.id(), 0);
  int fbw = 0, fbh = 0;
  glfwGetFramebufferSize(window_, &fbw, &fbh);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  // Row 0 of the image is its top: flip while blitting to the bottom-up default framebuffer.
  glBlitNamedFramebuffer(fbo.id(), 0, 0, 0, width, height, 0, fbh, fbw, 0, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glfwSwapBuffers(window_);
  checkGl("presenting an image in the window");
}

void WindowContext::showUntilClosed(const unsigned char* rgba, int width, int height) {
  while (!shouldClose()) {
    present(rgba, width, height);
    glfwWaitEventsTimeout(0.1);
    if (glfwGetKey(window_, GLFW_KEY_ESCAPE) == GLFW_PRESS) break;
  }
}

std::unique_ptr<WindowContext> createWindowContext(int width, int height, const std::string& title) {
  hostPassesSetting();  // a wrong TLAB_HOST_PASSES is one line before any work (as headless)
  drawRunsSetting();    // and a wrong TLAB_DRAW_RUNS
  return std::make_unique<WindowContext>(width, height, title);
}

}  // namespace tlab::gpu
