#include "tasks/ray_layer_caster.hpp"

#include <algorithm>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace tlab::tasks {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point toPoint(glm::dvec3 p) { return {p.x, p.y, p.z}; }
glm::dvec3 toVec(const Point& p) { return {p.x(), p.y(), p.z()}; }
}  // namespace

struct RayLayerCaster::Tree {
  std::vector<Triangle> triangles;
  std::vector<int> objectOf;
  std::vector<int> triangleOf;  // index into the object's mesh triangles (degenerate ones are left out)
  AabbTree tree;
};

RayLayerCaster::RayLayerCaster(const render::Scene& scene) : tree_(std::make_unique<Tree>()) {
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const auto& mesh = scene.objects[o].mesh;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      const auto& t = mesh.triangles[i];
      const Triangle tri(toPoint(mesh.positions[t[0]]), toPoint(mesh.positions[t[1]]), toPoint(mesh.positions[t[2]]));
      if (tri.is_degenerate()) continue;
      tree_->triangles.push_back(tri);
      tree_->objectOf.push_back(int(o));
      tree_->triangleOf.push_back(int(i));
    }
  }
  tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
  tree_->tree.build();
}

RayLayerCaster::~RayLayerCaster() = default;
RayLayerCaster::RayLayerCaster(RayLayerCaster&&) noexcept = default;
RayLayerCaster& RayLayerCaster::operator=(RayLayerCaster&&) noexcept = default;

std::vector<RayHit> RayLayerCaster::hits(const Ray& ray, double mergeDistance) const {
  if (tree_->triangles.empty()) return {};
  const Kernel::Ray_3 query(toPoint(ray.origin), Kernel::Vector_3(ray.direction.x, ray.direction.y, ray.direction.z));
  using Intersection = AabbTree::Intersection_and_primitive_id<Kernel::Ray_3>::Type;
  std::vector<Intersection> found;
  tree_->tree.all_intersections(query, std::back_inserter(found));
  std::vector<RayHit> all;
  for (const auto& [where, id] : found) {
    const std::size_t index = std::size_t(id - tree_->triangles.cbegin());
    const int object = tree_->objectOf[index];
    double distance = 0.0;
    if (const Point* p = boost::get<Point>(&where)) {
      distance = glm::dot(toVec(*p) - ray.origin, ray.direction);
    } else if (const Segment* s = boost::get<Segment>(&where)) {  // the ray lies in the triangle's plane
      distance = std::min(glm::dot(toVec(s->source()) - ray.origin, ray.direction),
                          glm::dot(toVec(s->target()) - ray.origin, ray.direction));
    } else {
      continue;
    }
    if (distance > 0.0) all.push_back({distance, object, tree_->triangleOf[index]});
  }
  std::sort(all.begin(), all.end(), [](const RayHit& a, const RayHit& b) { return a.distance < b.distance; });
  std::vector<RayHit> merged;
  for (const auto& h : all)
    if (merged.empty() || h.distance - merged.back().distance > mergeDistance) merged.push_back(h);
  return merged;
}

}  // namespace tlab::tasks
