#include "renderer/scene/gltf_writer.hpp"

#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

namespace tlab::render {

namespace {

// Appends `bytes` to the one buffer as a view (4-byte aligned) and returns the view's index.
int addView(tinygltf::Model& model, const void* bytes, std::size_t size, int target) {
  auto& data = model.buffers[0].data;
  while (data.size() % 4) data.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = size;
  view.target = target;
  const auto* p = static_cast<const unsigned char*>(bytes);
  data.insert(data.end(), p, p + size);
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size()) - 1;
}

int addAccessor(tinygltf::Model& model, int view, int componentType, std::size_t count, int type) {
  tinygltf::Accessor a;
  a.bufferView = view;
  a.componentType = componentType;
  a.count = count;
  a.type = type;
  model.accessors.push_back(a);
  return int(model.accessors.size()) - 1;
}

int addObjectMesh(tinygltf::Model& model, const SceneObject& object) {
  const TriangleMesh& m = object.mesh;
  tinygltf::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  const int positions = addAccessor(model, addView(model, m.positions.data(), m.positions.size() * 12, TINYGLTF_TARGET_ARRAY_BUFFER),
                                    TINYGLTF_COMPONENT_TYPE_FLOAT, m.positions.size(), TINYGLTF_TYPE_VEC3);
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const auto& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  model.accessors[positions].minValues = {lo.x, lo.y, lo.z};
  model.accessors[positions].maxValues = {hi.x, hi.y, hi.z};
  prim.attributes["POSITION"] = positions;
  if (m.normals.size() == m.positions.size())
    prim.attributes["NORMAL"] = addAccessor(model, addView(model, m.normals.data(), m.normals.size() * 12, TINYGLTF_TARGET_ARRAY_BUFFER),
                                            TINYGLTF_COMPONENT_TYPE_FLOAT, m.normals.size(), TINYGLTF_TYPE_VEC3);
  prim.indices = addAccessor(model, addView(model, m.triangles.data(), m.triangles.size() * 12, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                             TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, m.triangles.size() * 3, TINYGLTF_TYPE_SCALAR);
  tinygltf::Material material;
  material.name = object.name;
  material.pbrMetallicRoughness.baseColorFactor = {object.frontColor.r, object.frontColor.g, object.frontColor.b, 1.0};
  material.doubleSided = true;
  model.materials.push_back(material);
  prim.material = int(model.materials.size()) - 1;
  tinygltf::Mesh mesh;
  mesh.name = object.name;
  mesh.primitives.push_back(prim);
  model.meshes.push_back(mesh);
  return int(model.meshes.size()) - 1;
}

tinygltf::Value vec(glm::vec3 v) { return tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(v.x), tinygltf::Value(v.y), tinygltf::Value(v.z)}); }

tinygltf::Value stringList(const std::vector<std::string>& words) {
  tinygltf::Value::Array a;
  for (const auto& w : words) a.emplace_back(w);
  return tinygltf::Value(a);
}

// The camera node: its world matrix is the inverse of tlab's view matrix (the eye at the origin,
// looking down −Z, +Y up), so a glTF reader places the camera exactly where tlab's is.
tinygltf::Node cameraNode(tinygltf::Model& model, const Camera& camera, int width, int height) {
  tinygltf::Camera c;
  c.type = "perspective";
  c.name = "tlab-camera";
  c.perspective.yfov = glm::radians(double(camera.fovyDegrees));
  c.perspective.aspectRatio = double(width) / double(height);
  c.perspective.znear = camera.nearPlane;
  c.perspective.zfar = camera.farPlane;
  model.cameras.push_back(c);
  tinygltf::Node node;
  node.name = "tlab-camera";
  node.camera = int(model.cameras.size()) - 1;
  const glm::mat4 world = glm::inverse(camera.view());
  node.matrix.assign(glm::value_ptr(world), glm::value_ptr(world) + 16);
  return node;
}

}  // namespace

std::vector<std::string> roleNames(Role roles) {
  std::vector<std::string> names;
  const std::pair<Role, const char*> all[] = {{Role::Transparent, "transparent"}, {Role::Opaque, "opaque"}, {Role::Target, "target"},
                                              {Role::Distractor, "distractor"}, {Role::Impenetrable, "impenetrable"}};
  for (const auto& [r, n] : all)
    if (hasRole(roles, r)) names.push_back(n);
  return names;
}

void writeGltfFile(const Scene& scene, const Camera& camera, int width, int height, const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext != ".glb" && ext != ".gltf") throw std::invalid_argument(path + ": the output must end in .glb or .gltf");
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "tlab scene export";
  model.buffers.emplace_back();
  tinygltf::Scene s;
  s.name = scene.name;
  for (const auto& object : scene.objects) {
    tinygltf::Node node;
    node.name = object.name;
    node.mesh = addObjectMesh(model, object);
    node.extras = tinygltf::Value(tinygltf::Value::Object{
        {"tlab_roles", stringList(roleNames(object.roles))},
        {"tlab_group", tinygltf::Value(object.group)},
        {"tlab_back_color", vec(glm::vec3(object.backColor))}});
    model.nodes.push_back(node);
    s.nodes.push_back(int(model.nodes.size()) - 1);
  }
  model.nodes.push_back(cameraNode(model, camera, width, height));
  s.nodes.push_back(int(model.nodes.size()) - 1);
  s.extras = tinygltf::Value(tinygltf::Value::Object{
      {"tlab_background", vec(glm::vec3(scene.background))},
      {"tlab_image_size", tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(width), tinygltf::Value(height)})},
      {"tlab_camera", tinygltf::Value(tinygltf::Value::Object{{"eye", vec(camera.eye)}, {"target", vec(camera.target)},
                                                              {"up", vec(camera.up)}, {"fovy_degrees", tinygltf::Value(double(camera.fovyDegrees))},
                                                              {"near", tinygltf::Value(double(camera.nearPlane))},
                                                              {"far", tinygltf::Value(double(camera.farPlane))}})}});
  model.scenes.push_back(s);
  model.defaultScene = 0;
  tinygltf::TinyGLTF writer;
  const bool binary = ext == ".glb";
  if (!writer.WriteGltfSceneToFile(&model, path, true, true, true, binary))
    throw std::runtime_error(path + ": cannot write the glTF file");
}

}  // namespace tlab::render
