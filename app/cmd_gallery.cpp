// tlab gallery: every style on the same scene, as PNGs in one folder.
#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "app/scene_options.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "renderer/image/image.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/styles/style.hpp"

namespace tlab::app {

namespace {

struct GalleryOptions {
  std::string out = "out/gallery";
  std::string scene = "builtin:open-cylinders";
  std::string size = "384x384";
};

void runGallery(const GalleryOptions& o) {
  const auto [w, h] = parseSize(o.size);
  std::filesystem::create_directories(o.out);
  const auto context = gpu::createHeadlessContext();
  render::Renderer renderer(render::loadScene(o.scene, sceneCatalog()));
  for (const auto& style : render::styleNames()) {
    render::RenderRequest q;
    q.width = w;
    q.height = h;
    q.style = style;
    const auto path = (std::filesystem::path(o.out) / (style + ".png")).string();
    render::writeFileAtomically(path, render::encodePng(renderer.render(q)));
    std::cout << "  " << style << ": " << path << "  (" << render::findStyle(style).description() << ")\n";
  }
  std::cout << "gallery of " << render::styleNames().size() << " styles on " << o.scene << " written to " << o.out << "/\n";
}

}  // namespace

void addGalleryCommand(CLI::App& app) {
  auto o = std::make_shared<GalleryOptions>();
  auto* cmd = app.add_subcommand("gallery", "Render every transparency style on the same scene");
  cmd->add_option("--out", o->out, "output folder")->capture_default_str();
  cmd->add_option("--scene", o->scene, "scene source")->capture_default_str();
  cmd->add_option("--size", o->size, "image size WxH")->capture_default_str();
  cmd->callback([o] { runGallery(*o); });
}

}  // namespace tlab::app
