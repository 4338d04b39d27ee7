#pragma once
#include <string>

#include "renderer/gpu/gpu_context.hpp"

struct GLFWwindow;

namespace tlab::gpu {

// A GLFW window owning a GL 4.5 core context.
class WindowContext final : public GpuContext {
 public:
  WindowContext(int width, int height, const std::string& title);
  ~WindowContext() override;
  std::string backendName() const override { return "glfw"; }
  bool isWindow() const override { return true; }
  GLFWwindow* handle() const { return window_; }
  bool shouldClose() const;
  // Shows an RGBA8 image (row 0 = top, width*height*4 bytes) scaled to the window, and swaps.
  void present(const unsigned char* rgba, int width, int height);
  // Shows the image until the user closes the window or presses Escape.
  void showUntilClosed(const unsigned char* rgba, int width, int height);

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace tlab::gpu
