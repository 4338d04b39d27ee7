#include "study/run/responder.hpp"

#include <nlohmann/json.hpp>

namespace tlab::study {

std::string DisplayInfo::json() const {
  return nlohmann::json{{"gl_backend", glBackend},
                        {"gl_vendor", glVendor},
                        {"gl_renderer", glRenderer},
                        {"gl_version", glVersion},
                        {"window", {windowWidth, windowHeight}},
                        {"framebuffer", {framebufferWidth, framebufferHeight}},
                        {"refresh_hz", refreshHz},
                        {"swap_interval", swapInterval}}
      .dump();
}

}  // namespace tlab::study
