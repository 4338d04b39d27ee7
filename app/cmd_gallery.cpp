// tlab gallery: every style on the same scene, as PNGs in one folder.
#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "app/scene_options.hpp"
#include "renderer/gpu/gpu_context.hpp"
#include "core/image.hpp"
#include "renderer/scene/scene_source.hpp"
#include "renderer/styles/style.hpp"
#include "stimuli/sets/label_painter.hpp"

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
  // Every style to its own PNG, and all of them on one labelled contact sheet (4 per row).
  const auto styles = render::styleNames();
  const int columns = 4, rows = int((styles.size() + columns - 1) / columns);
  core::Image sheet(columns * w, rows * h, glm::vec4(1.0f));
  const stimuli::LabelPainter painter;
  for (std::size_t i = 0; i < styles.size(); ++i) {
    render::RenderRequest q;
    q.width = w;
    q.height = h;
    q.style = styles[i];
    const core::Image image = renderer.render(q);
    const auto path = (std::filesystem::path(o.out) / (styles[i] + ".png")).string();
    core::writeFileAtomically(path, core::encodePng(image));
    std::cout << "  " << styles[i] << ": " << path << "  (" << render::findStyle(styles[i]).description() << ")\n";
    const int x0 = int(i % columns) * w, y0 = int(i / columns) * h;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) sheet.at(x0 + x, y0 + y) = image.at(x, y);
    painter.drawText(sheet, x0 + 6, y0 + 6, styles[i], h * 0.07, glm::vec4(0, 0, 0, 1));
  }
  const auto sheetPath = (std::filesystem::path(o.out) / "gallery.png").string();
  core::writeFileAtomically(sheetPath, core::encodePng(sheet));
  std::cout << "  contact sheet: " << sheetPath << "\n";
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
