#include "renderer/styles/opaque_style.hpp"

#include "renderer/compose/raster_pass.hpp"

namespace tlab::render {

std::vector<std::unique_ptr<RenderPass>> OpaqueStyle::passes(const StyleParams&) const {
  std::vector<std::unique_ptr<RenderPass>> p;
  p.push_back(functionPass("raster", [](FrameContext& f) { rasterScene(f, RasterMode::ZBuffer); }));
  return p;
}

}  // namespace tlab::render
