#include "renderer/scene/gltf_loader.hpp"

#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace tlab::render {

namespace {

class GltfError : public std::runtime_error {
 public:
  GltfError(const std::string& file, const std::string& what) : std::runtime_error(file + ": " + what) {}
};

std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// Reads accessor element `i`, component `c` as a double (normalised integers mapped to [0,1] or
// [-1,1] when the accessor says so).
class AccessorReader {
 public:
  AccessorReader(const tinygltf::Model& model, int accessorIndex, const std::string& file) : file_(file) {
    if (accessorIndex < 0 || accessorIndex >= int(model.accessors.size()))
      throw GltfError(file, "accessor " + std::to_string(accessorIndex) + " does not exist");
    acc_ = &model.accessors[accessorIndex];
    if (acc_->sparse.isSparse) throw GltfError(file, "sparse accessors are not supported");
    if (acc_->bufferView < 0 || acc_->bufferView >= int(model.bufferViews.size()))
      throw GltfError(file, "accessor " + std::to_string(accessorIndex) + " has no buffer view");
    const auto& view = model.bufferViews[acc_->bufferView];
    if (view.buffer < 0 || view.buffer >= int(model.buffers.size()))
      throw GltfError(file, "buffer view " + std::to_string(acc_->bufferView) + " names a missing buffer");
    const auto& buffer = model.buffers[view.buffer];
    components_ = tinygltf::GetNumComponentsInType(acc_->type);
    componentSize_ = tinygltf::GetComponentSizeInBytes(acc_->componentType);
    if (components_ <= 0 || componentSize_ <= 0)
      throw GltfError(file, "accessor " + std::to_string(accessorIndex) + " has an unknown type");
    stride_ = acc_->ByteStride(view);
    if (stride_ <= 0) throw GltfError(file, "accessor " + std::to_string(accessorIndex) + " has an invalid byte stride");
    base_ = view.byteOffset + acc_->byteOffset;
    const std::size_t need = acc_->count == 0 ? 0 : base_ + std::size_t(stride_) * (acc_->count - 1) + std::size_t(components_ * componentSize_);
    if (need > view.byteOffset + view.byteLength || need > buffer.data.size())
      throw GltfError(file, "accessor " + std::to_string(accessorIndex) + " reads past the end of its buffer");
    data_ = buffer.data.data();
  }
  std::size_t count() const { return acc_->count; }
  int components() const { return components_; }
  double get(std::size_t i, int c) const {
    const unsigned char* p = data_ + base_ + i * std::size_t(stride_) + std::size_t(c * componentSize_);
    switch (acc_->componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: { float v; std::memcpy(&v, p, 4); return v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: { return acc_->normalized ? p[0] / 255.0 : p[0]; }
      case TINYGLTF_COMPONENT_TYPE_BYTE: { const auto v = static_cast<signed char>(p[0]); return acc_->normalized ? std::max(v / 127.0, -1.0) : v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { std::uint16_t v; std::memcpy(&v, p, 2); return acc_->normalized ? v / 65535.0 : v; }
      case TINYGLTF_COMPONENT_TYPE_SHORT: { std::int16_t v; std::memcpy(&v, p, 2); return acc_->normalized ? std::max(v / 32767.0, -1.0) : v; }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t v; std::memcpy(&v, p, 4); return v; }
      default: throw GltfError(file_, "unsupported accessor component type " + std::to_string(acc_->componentType));
    }
  }

 private:
  const tinygltf::Accessor* acc_ = nullptr;
  const unsigned char* data_ = nullptr;
  std::size_t base_ = 0;
  int stride_ = 0, components_ = 0, componentSize_ = 0;
  std::string file_;
};

glm::mat4 localTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(node.matrix[i]);  // column-major, as glTF
    return m;
  }
  glm::mat4 m(1.0f);
  if (node.translation.size() == 3)
    m = glm::translate(m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
  if (node.rotation.size() == 4)
    m *= glm::mat4_cast(glm::quat(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]), float(node.rotation[2])));
  if (node.scale.size() == 3) m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

std::vector<std::array<std::uint32_t, 3>> triangulate(int mode, const std::vector<std::uint32_t>& idx, const std::string& file) {
  std::vector<std::array<std::uint32_t, 3>> tris;
  switch (mode) {
    case TINYGLTF_MODE_TRIANGLES:
      for (std::size_t i = 0; i + 2 < idx.size(); i += 3) tris.push_back({idx[i], idx[i + 1], idx[i + 2]});
      break;
    case TINYGLTF_MODE_TRIANGLE_STRIP:
      for (std::size_t i = 0; i + 2 < idx.size(); ++i)
        tris.push_back(i % 2 == 0 ? std::array{idx[i], idx[i + 1], idx[i + 2]} : std::array{idx[i + 1], idx[i], idx[i + 2]});
      break;
    case TINYGLTF_MODE_TRIANGLE_FAN:
      for (std::size_t i = 1; i + 1 < idx.size(); ++i) tris.push_back({idx[0], idx[i], idx[i + 1]});
      break;
    default:
      (void)file;  // points and lines carry no surface: skipped
      break;
  }
  return tris;
}

TriangleMesh convertPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& prim, const std::string& file) {
  TriangleMesh mesh;
  const auto posIt = prim.attributes.find("POSITION");
  if (posIt == prim.attributes.end()) throw GltfError(file, "a mesh primitive has no POSITION attribute");
  const AccessorReader pos(model, posIt->second, file);
  if (pos.components() != 3) throw GltfError(file, "POSITION must be VEC3");
  mesh.positions.resize(pos.count());
  for (std::size_t i = 0; i < pos.count(); ++i) {
    mesh.positions[i] = glm::vec3(pos.get(i, 0), pos.get(i, 1), pos.get(i, 2));
    if (!std::isfinite(mesh.positions[i].x) || !std::isfinite(mesh.positions[i].y) || !std::isfinite(mesh.positions[i].z))
      throw GltfError(file, "POSITION has a non-finite value");
  }
  mesh.st.assign(pos.count(), glm::vec2(0.0f));
  if (const auto it = prim.attributes.find("TEXCOORD_0"); it != prim.attributes.end()) {
    const AccessorReader tc(model, it->second, file);
    if (tc.count() != pos.count() || tc.components() != 2) throw GltfError(file, "TEXCOORD_0 must be VEC2 with one value per vertex");
    for (std::size_t i = 0; i < tc.count(); ++i) mesh.st[i] = glm::vec2(tc.get(i, 0), tc.get(i, 1));
  }
  std::vector<std::uint32_t> idx;
  if (prim.indices >= 0) {
    const AccessorReader ind(model, prim.indices, file);
    idx.resize(ind.count());
    for (std::size_t i = 0; i < ind.count(); ++i) {
      const double v = ind.get(i, 0);
      if (v < 0 || v >= double(pos.count())) throw GltfError(file, "index " + std::to_string(std::llround(v)) + " is out of range");
      idx[i] = static_cast<std::uint32_t>(v);
    }
  } else {
    idx.resize(pos.count());
    for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<std::uint32_t>(i);
  }
  mesh.triangles = triangulate(prim.mode, idx, file);
  const auto nIt = prim.attributes.find("NORMAL");
  if (nIt != prim.attributes.end()) {
    const AccessorReader nor(model, nIt->second, file);
    if (nor.count() != pos.count() || nor.components() != 3) throw GltfError(file, "NORMAL must be VEC3 with one value per vertex");
    mesh.normals.resize(nor.count());
    for (std::size_t i = 0; i < nor.count(); ++i) {
      glm::vec3 n(nor.get(i, 0), nor.get(i, 1), nor.get(i, 2));
      const float len = glm::length(n);
      mesh.normals[i] = (len > 0 && std::isfinite(len)) ? n / len : glm::vec3(0, 0, 1);
    }
  } else {
    computeVertexNormals(mesh);
  }
  return mesh;
}

Camera cameraFromNode(const tinygltf::Camera& cam, const glm::mat4& world) {
  Camera c;
  c.eye = glm::vec3(world * glm::vec4(0, 0, 0, 1));
  const glm::vec3 forward = glm::normalize(glm::vec3(world * glm::vec4(0, 0, -1, 0)));
  c.target = c.eye + forward;
  c.up = glm::normalize(glm::vec3(world * glm::vec4(0, 1, 0, 0)));
  c.fovyDegrees = static_cast<float>(glm::degrees(cam.perspective.yfov));
  c.nearPlane = static_cast<float>(cam.perspective.znear);
  c.farPlane = cam.perspective.zfar > 0 ? static_cast<float>(cam.perspective.zfar) : c.nearPlane * 1e4f;
  return c;
}

Scene convertModel(const tinygltf::Model& model, const std::string& file) {
  Scene scene;
  scene.name = std::filesystem::path(file).stem().string();
  std::vector<int> roots;
  const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (sceneIndex < int(model.scenes.size())) roots = model.scenes[sceneIndex].nodes;
  else
    for (int i = 0; i < int(model.nodes.size()); ++i) roots.push_back(i);  // no scenes: every node is a root
  std::vector<int> depthGuard(model.nodes.size(), 0);
  std::function<void(int, const glm::mat4&)> visit = [&](int nodeIndex, const glm::mat4& parent) {
    if (nodeIndex < 0 || nodeIndex >= int(model.nodes.size())) throw GltfError(file, "node " + std::to_string(nodeIndex) + " does not exist");
    if (depthGuard[nodeIndex]++ > 0) throw GltfError(file, "node " + std::to_string(nodeIndex) + " is reached twice (cycle in the node hierarchy)");
    const auto& node = model.nodes[nodeIndex];
    const glm::mat4 world = parent * localTransform(node);
    if (node.camera >= 0 && node.camera < int(model.cameras.size()) && !scene.camera && model.cameras[node.camera].type == "perspective")
      scene.camera = cameraFromNode(model.cameras[node.camera], world);
    if (node.mesh >= 0) {
      if (node.mesh >= int(model.meshes.size())) throw GltfError(file, "node " + std::to_string(nodeIndex) + " names a missing mesh");
      const auto& mesh = model.meshes[node.mesh];
      for (const auto& prim : mesh.primitives) {
        SceneObject obj;
        obj.name = mesh.name.empty() ? "mesh-" + std::to_string(node.mesh) : mesh.name;
        obj.mesh = convertPrimitive(model, prim, file);
        if (obj.mesh.triangles.empty()) continue;
        transformMesh(obj.mesh, world);
        if (prim.material >= 0 && prim.material < int(model.materials.size())) {
          const auto& f = model.materials[prim.material].pbrMetallicRoughness.baseColorFactor;
          if (f.size() == 4) obj.frontColor = glm::vec4(f[0], f[1], f[2], 1.0f);
        }
        obj.backColor = glm::vec4(glm::vec3(obj.frontColor) * 0.55f + glm::vec3(0.1f, 0.15f, 0.3f), 1.0f);
        scene.objects.push_back(std::move(obj));
      }
    }
    for (int child : node.children) visit(child, world);
  };
  for (int root : roots) visit(root, glm::mat4(1.0f));
  requireTriangles(scene, file);
  return scene;
}

}  // namespace

Scene loadGltfFromMemory(const std::vector<unsigned char>& bytes, const std::string& name, bool binary, const std::string& baseDir) {
  tinygltf::TinyGLTF loader;
  // Images are not used (colours come from materials): skip decoding them.
  loader.SetImageLoader(
      [](tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) { return true; },
      nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const bool ok = binary
      ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()), baseDir)
      : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()), static_cast<unsigned int>(bytes.size()), baseDir);
  if (!ok) throw GltfError(name, "not a valid glTF 2.0 file: " + oneLine(err.empty() ? "unknown error" : err));
  return convertModel(model, name);
}

Scene loadGltfFile(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw std::runtime_error(path + ": no such file");
  if (fs::is_directory(path, ec)) throw std::runtime_error(path + ": is a directory, not a glTF file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  const std::string ext = fs::path(path).extension().string();
  if (!binary && ext != ".gltf" && ext != ".glb")
    throw std::runtime_error(path + ": not a glTF file (expected .gltf or .glb)");
  return loadGltfFromMemory(bytes, path, binary, fs::path(path).parent_path().string());
}

}  // namespace tlab::render
