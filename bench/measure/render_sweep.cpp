#include "bench/measure/render_sweep.hpp"

#include "bench/measure/frame_timing.hpp"
#include "renderer/scene/scene_source.hpp"

namespace tlab::bench {

RenderSweepRow measureRenderSweep(const std::string& sweep, const std::string& source, int size, render::FillMethod fill,
                                  const std::string& style, int repeats) {
  render::Renderer renderer(render::loadScene(source));
  render::RenderRequest q;
  q.width = q.height = size;
  q.style = style;
  q.fill = fill;
  RenderSweepRow row{sweep, source, size, renderer.scene().triangleCount(), render::fillMethodName(fill)};
  const FrameTiming t = timeFrames(renderer, q, repeats);
  row.passes = t.passes;
  row.fragments = t.fragments;
  row.listMs = passSum(row.passes);
  render::RenderRequest floor = q;
  floor.style = "unsorted";
  row.floorMs = passSum(timeFrames(renderer, floor, repeats).passes);
  return row;
}

}  // namespace tlab::bench
