#include "renderer/frame/gpu_scene.hpp"

#include <algorithm>
#include <vector>

#include "renderer/gpu/gl_error.hpp"

namespace tlab::render {

namespace {
constexpr GLuint kBindObjects = 8;  // BIND_OBJECTS in frame/fragment_layout.glsl

struct ObjectRecord {
  glm::vec4 front, back;
  std::uint32_t roles, group, componentOffset, unused;
};

template <typename T>
gpu::Buffer makeBuffer(const std::vector<T>& v) {
  return gpu::Buffer(v.size() * sizeof(T), v.empty() ? nullptr : v.data());
}
}  // namespace

GpuScene::GpuScene(const Scene& scene) : bounds_(scene.boundingBox()) {
  std::vector<glm::vec3> pos, nor;
  std::vector<glm::vec2> st;
  std::vector<std::uint32_t> obj, comp, idx;
  std::vector<ObjectRecord> records;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const auto& object = scene.objects[o];
    const auto& mesh = object.mesh;
    const auto base = static_cast<std::uint32_t>(pos.size());
    const auto components = connectedComponents(mesh);
    std::uint32_t maxComponent = 0;
    for (auto c : components) maxComponent = std::max(maxComponent, c + 1);
    records.push_back({object.frontColor, object.backColor, std::uint32_t(object.roles),
                       std::uint32_t(object.group), componentCount_, 0});
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      pos.push_back(mesh.positions[v]);
      nor.push_back(v < mesh.normals.size() ? mesh.normals[v] : glm::vec3(0, 0, 1));
      st.push_back(v < mesh.st.size() ? mesh.st[v] : glm::vec2(0));
      obj.push_back(static_cast<std::uint32_t>(o));
      comp.push_back(componentCount_ + components[v]);
    }
    for (const auto& t : mesh.triangles) idx.insert(idx.end(), {t[0] + base, t[1] + base, t[2] + base});
    componentCount_ += maxComponent;
  }
  triangleCount_ = idx.size() / 3;
  positions_ = makeBuffer(pos);
  normals_ = makeBuffer(nor);
  st_ = makeBuffer(st);
  objectIds_ = makeBuffer(obj);
  componentIds_ = makeBuffer(comp);
  indices_ = makeBuffer(idx);
  objectTable_ = makeBuffer(records);
  vao_ = gpu::makeVertexArray();
  const GLuint vao = vao_.id();
  const auto attribute = [&](GLuint loc, const gpu::Buffer& b, GLint n, GLenum type, GLsizei stride, bool integer) {
    glEnableVertexArrayAttrib(vao, loc);
    glVertexArrayVertexBuffer(vao, loc, b.id(), 0, stride);
    if (integer) glVertexArrayAttribIFormat(vao, loc, n, type, 0);
    else glVertexArrayAttribFormat(vao, loc, n, type, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, loc, loc);
  };
  attribute(0, positions_, 3, GL_FLOAT, sizeof(glm::vec3), false);
  attribute(1, normals_, 3, GL_FLOAT, sizeof(glm::vec3), false);
  attribute(2, st_, 2, GL_FLOAT, sizeof(glm::vec2), false);
  attribute(3, objectIds_, 1, GL_UNSIGNED_INT, 4, true);
  attribute(4, componentIds_, 1, GL_UNSIGNED_INT, 4, true);
  glVertexArrayElementBuffer(vao, indices_.id());
  gpu::checkGl("uploading the scene");
  const std::optional<std::size_t> runs = gpu::drawRunsSetting();
  runs_ = runs ? *runs : defaultDrawRuns(triangleCount_, gpu::glRunsOnCpu());
}

void GpuScene::bindObjectTable() const { objectTable_.bindBase(GL_SHADER_STORAGE_BUFFER, kBindObjects); }

void GpuScene::draw(GLint primitiveBase) const {
  glBindVertexArray(vao_.id());
  const std::size_t runs = std::max<std::size_t>(1, std::min(runs_, triangleCount_));
  for (std::size_t r = 0; r < runs; ++r) {
    const std::size_t first = triangleCount_ * r / runs, end = triangleCount_ * (r + 1) / runs;
    if (primitiveBase >= 0) glUniform1ui(primitiveBase, static_cast<GLuint>(first));
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>((end - first) * 3), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(first * 3 * sizeof(std::uint32_t)));
    if (runs > 1) glFlush();
  }
  glBindVertexArray(0);
}

std::size_t defaultDrawRuns(std::size_t triangles, bool glOnCpu) {
  if (!glOnCpu) return 1;
  return std::clamp<std::size_t>(triangles / kTrianglesPerDrawRun, 1, kMaxDrawRuns);
}

}  // namespace tlab::render
