// tlab scene export SCENE -o scene.glb: any scene (built-in or glTF) as glTF 2.0, with its
// objects, roles and the camera tlab draws it with, for another renderer to draw the same view.
#include <iostream>

#include "app/commands.hpp"
#include "app/scene_options.hpp"
#include "renderer/scene/gltf_writer.hpp"
#include "renderer/scene/scene_source.hpp"

namespace tlab::app {

namespace {

struct SceneExportOptions {
  std::string scene;
  std::string output;
  std::string size = "512x512";
  std::string camera;
};

void runExport(const SceneExportOptions& o) {
  const render::Scene scene = render::loadScene(o.scene, sceneCatalog());
  SceneOptions options;  // the camera exactly as `tlab render` resolves it
  options.scene = o.scene;
  options.size = o.size;
  options.camera = o.camera;
  const render::RenderRequest request = options.request(scene);
  const render::Camera camera = request.camera  ? *request.camera
                                : scene.camera ? *scene.camera
                                               : render::fitCamera(scene.boundingSphere(), float(request.width) / float(request.height));
  render::writeGltfFile(scene, camera, request.width, request.height, o.output);
  std::cout << "wrote " << o.output << " (" << scene.objects.size() << " objects, camera eye " << camera.eye.x << "," << camera.eye.y
            << "," << camera.eye.z << " fovy " << camera.fovyDegrees << " for " << request.width << "x" << request.height << ")\n";
}

}  // namespace

void addSceneCommand(CLI::App& app) {
  auto* scene = app.add_subcommand("scene", "Scenes leaving tlab: export one for another renderer");
  scene->require_subcommand(1);
  auto options = std::make_shared<SceneExportOptions>();
  auto* cmd = scene->add_subcommand("export", "Write a scene as glTF 2.0 with its objects, roles and tlab's camera (see the README's camera conventions)");
  cmd->add_option("scene", options->scene, "a glTF file (.gltf/.glb) or builtin:NAME[?param=value&...]")->required();
  cmd->add_option("-o,--output", options->output, "output .glb (binary) or .gltf (JSON, buffer embedded)")->required();
  cmd->add_option("--size", options->size, "the image size WxH the camera is for (its aspect ratio)")->capture_default_str();
  cmd->add_option("--camera", options->camera, "\"eye=X,Y,Z target=X,Y,Z up=X,Y,Z fovy=DEG [near=N far=F]\" as for tlab render");
  cmd->callback([options] { runExport(*options); });
}

}  // namespace tlab::app
