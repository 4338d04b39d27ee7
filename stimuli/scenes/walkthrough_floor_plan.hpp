#pragma once
// Elmqvist's WALKTHROUGH floor plan (seed 004): a grid of square rooms; neighbouring rooms are joined
// by doorways. The plan is a random spanning tree of the grid (every room reachable) plus a share of
// extra doorways that make loops, all from a seed. World coordinates: room (i, j) covers
// x ∈ [i·s, (i+1)·s], z ∈ [j·s, (j+1)·s] on the floor y = 0 (s = roomSize).
#include <cstdint>
#include <vector>

#include "core/image.hpp"

namespace tlab::stimuli {

class WalkthroughFloorPlan {
 public:
  static WalkthroughFloorPlan random(std::uint64_t seed, int columns = 16, int rows = 16, double extraDoorShare = 0.15,
                                     double roomSize = 4.0);

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  double roomSize() const { return roomSize_; }
  // Doorway between room (i, j) and (i + 1, j) / (i, j + 1).
  bool doorEast(int i, int j) const { return doorEast_[index(i, j)]; }
  bool doorSouth(int i, int j) const { return doorSouth_[index(i, j)]; }
  std::size_t doorCount() const;
  // Rooms reachable from room (0, 0) through doorways (breadth-first search).
  std::size_t reachableRooms() const;

 private:
  std::size_t index(int i, int j) const { return std::size_t(j) * std::size_t(columns_) + std::size_t(i); }
  int columns_ = 0, rows_ = 0;
  double roomSize_ = 4.0;
  std::vector<bool> doorEast_, doorSouth_;
};

// The top-down plan for answering (Elmqvist T3): white floor, black walls with doorway gaps, x to
// the right and z downward (the tasks' floor-plan convention), `pixelsPerRoom` per room.
core::Image floorPlanImage(const WalkthroughFloorPlan& plan, int pixelsPerRoom = 32);

}  // namespace tlab::stimuli
