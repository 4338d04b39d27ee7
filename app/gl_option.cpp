#include "app/gl_option.hpp"

#include "renderer/gpu/gl_backend.hpp"

namespace tlab::app {

namespace {

void addGlOption(CLI::App& cmd) {
  cmd.add_option_function<std::string>(
         "--gl", [](const std::string& v) { gpu::setGlChoice(gpu::parseGlChoice(v, "--gl")); },
         "headless OpenGL: auto (an EGL GPU, else Mesa's surfaceless EGL, else OSMesa), egl, egl:N (EGL device N) "
         "or osmesa; default: $TLAB_GL, else auto")
      ->type_name("auto|egl|egl:N|osmesa")
      ->check([](const std::string& v) {
        try {
          gpu::parseGlChoice(v, "");  // CLI11 names the option itself
          return std::string();
        } catch (const std::invalid_argument& e) {
          return std::string(e.what());
        }
      });
}

}  // namespace

void addGlOptions(CLI::App& app) {
  for (const char* name : {"render", "inspect", "gallery", "demo", "simulate", "stimuli", "run", "replay"})
    addGlOption(*app.get_subcommand(name));
  for (auto* bench : app.get_subcommand("bench")->get_subcommands({})) addGlOption(*bench);
}

nlohmann::json gpuInfoToJson(const gpu::GpuInfo& info) {
  return {{"backend", info.backend}, {"vendor", info.vendor}, {"renderer", info.renderer},
          {"version", info.version}, {"glsl_version", info.glslVersion}};
}

}  // namespace tlab::app
