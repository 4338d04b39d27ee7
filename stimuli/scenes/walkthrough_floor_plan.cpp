#include "stimuli/scenes/walkthrough_floor_plan.hpp"

#include <algorithm>
#include <deque>

#include "core/seeded_random.hpp"

namespace tlab::stimuli {

WalkthroughFloorPlan WalkthroughFloorPlan::random(std::uint64_t seed, int columns, int rows, double extraDoorShare, double roomSize) {
  WalkthroughFloorPlan plan;
  plan.columns_ = columns;
  plan.rows_ = rows;
  plan.roomSize_ = roomSize;
  const std::size_t n = std::size_t(columns) * std::size_t(rows);
  plan.doorEast_.assign(n, false);
  plan.doorSouth_.assign(n, false);
  core::SeededRandom random(seed);
  // Randomized depth-first search: a spanning tree, so every room is reachable.
  std::vector<bool> visited(n, false);
  std::vector<glm::ivec2> stack{{0, 0}};
  visited[0] = true;
  while (!stack.empty()) {
    const glm::ivec2 room = stack.back();
    std::vector<glm::ivec2> next;
    for (const glm::ivec2 d : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)}) {
      const glm::ivec2 r = room + d;
      if (r.x >= 0 && r.y >= 0 && r.x < columns && r.y < rows && !visited[plan.index(r.x, r.y)]) next.push_back(r);
    }
    if (next.empty()) {
      stack.pop_back();
      continue;
    }
    const glm::ivec2 r = next[random.below(std::uint32_t(next.size()))];
    const glm::ivec2 lo = glm::min(room, r);
    if (r.y == room.y) plan.doorEast_[plan.index(lo.x, lo.y)] = true;
    else plan.doorSouth_[plan.index(lo.x, lo.y)] = true;
    visited[plan.index(r.x, r.y)] = true;
    stack.push_back(r);
  }
  // Extra doorways: loops, so there is more than one way through the building.
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      if (i + 1 < columns && random.uniform() < extraDoorShare) plan.doorEast_[plan.index(i, j)] = true;
      if (j + 1 < rows && random.uniform() < extraDoorShare) plan.doorSouth_[plan.index(i, j)] = true;
    }
  return plan;
}

std::size_t WalkthroughFloorPlan::doorCount() const {
  return std::size_t(std::count(doorEast_.begin(), doorEast_.end(), true) + std::count(doorSouth_.begin(), doorSouth_.end(), true));
}

std::size_t WalkthroughFloorPlan::reachableRooms() const {
  std::vector<bool> seen(doorEast_.size(), false);
  std::deque<glm::ivec2> queue{{0, 0}};
  seen[0] = true;
  std::size_t count = 0;
  while (!queue.empty()) {
    const glm::ivec2 r = queue.front();
    queue.pop_front();
    ++count;
    const auto visit = [&](int i, int j) {
      if (!seen[index(i, j)]) seen[index(i, j)] = true, queue.push_back({i, j});
    };
    if (r.x + 1 < columns_ && doorEast(r.x, r.y)) visit(r.x + 1, r.y);
    if (r.x > 0 && doorEast(r.x - 1, r.y)) visit(r.x - 1, r.y);
    if (r.y + 1 < rows_ && doorSouth(r.x, r.y)) visit(r.x, r.y + 1);
    if (r.y > 0 && doorSouth(r.x, r.y - 1)) visit(r.x, r.y - 1);
  }
  return count;
}

core::Image floorPlanImage(const WalkthroughFloorPlan& plan, int ppr) {
  const int border = ppr / 2;
  core::Image image(plan.columns() * ppr + 2 * border, plan.rows() * ppr + 2 * border, glm::vec4(1.0f));
  const glm::vec4 wall(0.0f, 0.0f, 0.0f, 1.0f);
  const int thick = std::max(1, ppr / 12), door = ppr / 3;
  const auto fill = [&](int x0, int y0, int x1, int y1) {
    for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y)
      for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x) image.at(x, y) = wall;
  };
  // A wall along one side of a room, with a centred gap of `door` pixels when there is a doorway.
  const auto vertical = [&](int x, int y, bool open) {
    if (!open) return fill(x - thick, y - thick, x + thick, y + ppr + thick);
    fill(x - thick, y - thick, x + thick, y + (ppr - door) / 2);
    fill(x - thick, y + (ppr + door) / 2, x + thick, y + ppr + thick);
  };
  const auto horizontal = [&](int x, int y, bool open) {
    if (!open) return fill(x - thick, y - thick, x + ppr + thick, y + thick);
    fill(x - thick, y - thick, x + (ppr - door) / 2, y + thick);
    fill(x + (ppr + door) / 2, y - thick, x + ppr + thick, y + thick);
  };
  for (int j = 0; j < plan.rows(); ++j)
    for (int i = 0; i < plan.columns(); ++i) {
      const int x = border + i * ppr, y = border + j * ppr;
      if (i == 0) vertical(x, y, false);
      if (j == 0) horizontal(x, y, false);
      vertical(x + ppr, y, i + 1 < plan.columns() && plan.doorEast(i, j));
      horizontal(x, y + ppr, j + 1 < plan.rows() && plan.doorSouth(i, j));
    }
  return image;
}

}  // namespace tlab::stimuli
