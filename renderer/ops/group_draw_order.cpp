#include "renderer/ops/group_draw_order.hpp"

#include <map>
#include <numeric>
#include <utility>

namespace tlab::render {

namespace {
glm::vec3 boxCentre(const TriangleMesh& mesh) {
  if (mesh.positions.empty()) return glm::vec3(0.0f);
  glm::vec3 lo = mesh.positions.front(), hi = lo;
  for (const auto& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return 0.5f * (lo + hi);
}
}  // namespace

GroupDrawOrder::GroupDrawOrder(const Scene& scene) : objectCount_(scene.objects.size()) {
  std::map<int, std::size_t> groupOf;  // scene group id -> index into groups_
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& object = scene.objects[o];
    const bool impenetrable = hasRole(object.roles, Role::Impenetrable);
    if (object.group < 0 || impenetrable) {
      groups_.push_back({{std::uint32_t(o)}, glm::vec3(0.0f), impenetrable});
      continue;
    }
    const auto [it, added] = groupOf.try_emplace(object.group, groups_.size());
    if (added) groups_.push_back({});
    groups_[it->second].objects.push_back(std::uint32_t(o));
  }
  // A group's centre: the mean of its members' bounding-box centres.
  for (auto& g : groups_) {
    glm::vec3 sum(0.0f);
    for (auto o : g.objects) sum += boxCentre(scene.objects[o].mesh);
    g.centre = sum / float(g.objects.size());
  }
  order_.resize(groups_.size());
  std::iota(order_.begin(), order_.end(), std::size_t{0});
}

std::size_t GroupDrawOrder::update(glm::vec3 eye, glm::vec3 viewDirection) {
  const glm::vec3 v = glm::normalize(viewDirection);
  // The sort key: impenetrable groups first, then the signed view distance, farthest first.
  std::vector<float> distance(groups_.size());
  for (std::size_t g = 0; g < groups_.size(); ++g) distance[g] = glm::dot(groups_[g].centre - eye, v);
  const auto before = [&](std::size_t a, std::size_t b) {
    if (groups_[a].impenetrable != groups_[b].impenetrable) return groups_[a].impenetrable;
    return distance[a] > distance[b];
  };
  // Bubble sort from the previous order (seed 004, Alg. 1 line 1); stops after a pass without swaps.
  std::size_t swaps = 0;
  for (std::size_t end = order_.size(); end > 1; --end) {
    bool swapped = false;
    for (std::size_t i = 1; i < end; ++i)
      if (before(order_[i], order_[i - 1])) {
        std::swap(order_[i], order_[i - 1]);
        swapped = true;
        ++swaps;
      }
    if (!swapped) break;
  }
  return swaps;
}

std::vector<std::uint32_t> GroupDrawOrder::objectRanks() const {
  std::vector<std::uint32_t> rank(objectCount_, 0);
  std::uint32_t next = 0;
  for (auto g : order_)
    for (auto o : groups_[g].objects) rank[o] = next++;
  return rank;
}

std::vector<std::vector<std::uint32_t>> GroupDrawOrder::groupsInDrawOrder() const {
  std::vector<std::vector<std::uint32_t>> out;
  for (auto g : order_) out.push_back(groups_[g].objects);
  return out;
}

}  // namespace tlab::render
