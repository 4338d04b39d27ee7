#include "app/style_file_check.hpp"

#include "app/scene_options.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "renderer/gpu/shader_cache.hpp"
#include "renderer/styles/file_style.hpp"

namespace tlab::app {

namespace {

void compileOnCurrentContext(const std::vector<std::string>& styles) {
  gpu::ShaderCache shaders;
  for (const auto& s : styles)
    if (render::isStyleFilePath(s)) dynamic_cast<const render::FileStyle&>(render::findStyle(s)).compile(shaders);
}

bool anyFile(const std::vector<std::string>& styles) {
  for (const auto& s : styles)
    if (render::isStyleFilePath(s)) return true;
  return false;
}

}  // namespace

void compileStyleFiles(const std::vector<std::string>& styles) {
  if (!anyFile(styles)) return;
  const auto context = gpu::createHeadlessContext();
  compileOnCurrentContext(styles);
}

std::vector<study::ImageAlignment> checkExperimentOnGl(const study::Experiment& experiment) {
  std::vector<std::string> styles;
  for (const auto& u : experiment.styleFiles) styles.push_back(u.path);
  bool images = false;
  for (const auto& f : experiment.factors)
    for (const auto& l : f.levels) images = images || l.images.has_value();
  if (styles.empty() && !images) return {};
  const auto context = gpu::createHeadlessContext();
  compileOnCurrentContext(styles);
  return images ? study::checkExternalImages(experiment, sceneCatalog()) : std::vector<study::ImageAlignment>{};
}

}  // namespace tlab::app
