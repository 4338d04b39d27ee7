#pragma once
// --gl auto|egl|egl:N|osmesa on every command that renders (renderer/gpu/gl_backend.hpp).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "renderer/gpu/gpu_context.hpp"

namespace tlab::app {

// Adds --gl to the rendering commands of `app` (and to every `bench` subcommand).
void addGlOptions(CLI::App& app);

// The context's backend, vendor, renderer and versions as JSON (--stats-json, manifests).
nlohmann::json gpuInfoToJson(const gpu::GpuInfo& info);

}  // namespace tlab::app
