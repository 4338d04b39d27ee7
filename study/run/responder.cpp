#include "study/run/responder.hpp"

#include <chrono>

#include <nlohmann/json.hpp>

namespace tlab::study {

std::int64_t monotonicNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string DisplayInfo::json() const {
  nlohmann::json j{{"gl_backend", glBackend},
                        {"gl_vendor", glVendor},
                        {"gl_renderer", glRenderer},
                        {"gl_version", glVersion},
                        {"window", {windowWidth, windowHeight}},
                        {"framebuffer", {framebufferWidth, framebufferHeight}},
                        {"refresh_hz", refreshHz},
                        {"swap_interval", swapInterval}};
  if (!browserJson.empty()) j["browser"] = nlohmann::json::parse(browserJson);
  return j.dump();
}

}  // namespace tlab::study
