#include "renderer/gpu/gl_backend.hpp"

#include <cstdlib>
#include <mutex>
#include <optional>
#include <stdexcept>

namespace tlab::gpu {

namespace {
std::mutex choiceMutex;
std::optional<GlChoice> chosen;  // set by --gl
}  // namespace

GlChoice parseGlChoice(const std::string& text, const std::string& where) {
  if (text == "auto") return {GlBackend::Auto, -1};
  if (text == "osmesa") return {GlBackend::Osmesa, -1};
  if (text == "egl") return {GlBackend::Egl, -1};
  if (text.rfind("egl:", 0) == 0 && text.size() > 4 && text.size() < 8 &&
      text.find_first_not_of("0123456789", 4) == std::string::npos)
    return {GlBackend::Egl, std::stoi(text.substr(4))};
  throw std::invalid_argument((where.empty() ? "" : where + ": ") + "'" + text + "' is not auto, egl, egl:N (an EGL device index) or osmesa");
}

std::string glChoiceName(const GlChoice& c) {
  switch (c.backend) {
    case GlBackend::Osmesa: return "osmesa";
    case GlBackend::Egl: return c.eglDevice < 0 ? "egl" : "egl:" + std::to_string(c.eglDevice);
    default: return "auto";
  }
}

void setGlChoice(const GlChoice& choice) {
  const std::lock_guard lock(choiceMutex);
  chosen = choice;
}

GlChoice glChoice() {
  const std::lock_guard lock(choiceMutex);
  if (chosen) return *chosen;
  const char* env = std::getenv("TLAB_GL");
  if (env && *env) return parseGlChoice(env, "TLAB_GL");
  return {};
}

}  // namespace tlab::gpu
