#include "renderer/styles/unsorted_style.hpp"

#include "renderer/compose/raster_pass.hpp"

namespace tlab::render {

std::vector<ParamSpec> UnsortedStyle::params() const {
  return {ParamSpec::number("alpha", 0.25, 0.0, 1.0, "opacity of every layer")};
}

std::vector<std::unique_ptr<RenderPass>> UnsortedStyle::passes(const StyleParams& params) const {
  std::vector<std::unique_ptr<RenderPass>> p;
  p.push_back(functionPass("blend", [alpha = static_cast<float>(params.number("alpha"))](FrameContext& f) {
    rasterScene(f, RasterMode::UnsortedBlend, alpha);
  }));
  return p;
}

}  // namespace tlab::render
