#pragma once
// One row of `tlab bench render` (Carnecky Figs. 14-15): a scene at one size with one fill, the
// median ms per pass of a style and of plain unsorted blending on the same scene (the floor).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "renderer/pipeline/renderer.hpp"

namespace tlab::bench {

struct RenderSweepRow {
  std::string sweep, scene;
  int size = 0;
  std::size_t triangles = 0;
  std::string fill;
  std::uint64_t fragments = 0;
  std::vector<std::pair<std::string, double>> passes{};  // medians
  double listMs = 0, floorMs = 0;
};

RenderSweepRow measureRenderSweep(const std::string& sweep, const std::string& source, int size, render::FillMethod fill,
                                  const std::string& style, int repeats);

}  // namespace tlab::bench
