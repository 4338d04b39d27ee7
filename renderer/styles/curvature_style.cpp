#include "renderer/styles/curvature_style.hpp"

#include "renderer/compose/curvature_compositor.hpp"
#include "renderer/kbuffer/bucket_neighbors.hpp"
#include "renderer/ops/screen_space_curvature.hpp"

namespace tlab::render {

namespace {

CurvatureStylization stylizationOf(const StyleParams& params) {
  if (params.is("mode", "plain")) return CurvatureStylization::Plain;
  if (params.is("mode", "shading")) return CurvatureStylization::Shading;
  return CurvatureStylization::Transparency;
}

}  // namespace

std::vector<ParamSpec> CurvatureStyle::params() const {
  return {
      lightingParam("pbr"),  // Sec. 4.2: Disney BRDF and image-based lighting
      ParamSpec::number("k", 16, 1, 32, "fragments kept per pixel (the k of the k-buffer, Sec. 4.1)"),
      ParamSpec::choice("mode", "transparency", {"plain", "shading", "transparency"},
                        "plain k-buffer blending with constant alpha (Fig. 9a), mean-curvature shading (Fig. 6), "
                        "or mean-curvature shading and transparency (Figs. 7-8)"),
      ParamSpec::choice("query", "buckets", {"buckets", "brute-force"},
                        "neighbour search: the same-shape bucket of the adjacent pixel, or all its fragments (Sec. 6)"),
      ParamSpec::choice("shape_id", "object", {"object", "component"},
                        "what a shape is: the scene object, or the connected component of its mesh"),
      ParamSpec::number("scale", 0.25, 0, 1e6,
                        "s: kappa1 + kappa2 in units of 1/(s r), r the scene's bounding radius (a sphere of radius "
                        "r has kappa = tanh(2 s)); independent of the image size"),
      ParamSpec::number("alpha", 0.6, 0, 1, "opacity of every fragment in modes plain and shading"),
      ParamSpec::text("shading_tf", "fig6a",
                      "1-D shading transfer function of kappa: fig6a, fig6b, points:k=v,k=v,... or a PNG file"),
      ParamSpec::text("opacity_tf", "fig7a",
                      "2-D opacity transfer function of |kappa| and depth: fig7a, fig7b, grid:a,b/c,d (rows near to "
                      "far) or a PNG file"),
  };
}

FragmentProperties CurvatureStyle::properties(const StyleParams&, const SceneFacts&) const { return {}; }

FillSpec CurvatureStyle::fill(const StyleParams& params) const {
  KBufferSettings s;
  s.k = static_cast<std::uint32_t>(params.number("k"));
  s.buckets = stylizationOf(params) != CurvatureStylization::Plain;
  s.shapeId = params.is("shape_id", "component") ? ShapeIdSource::Component : ShapeIdSource::Object;
  return {FillSpec::Kind::BucketedKBuffer, s};
}

void CurvatureStyle::validate(const StyleParams& params) const {
  const double k = params.number("k");
  if (k != static_cast<double>(static_cast<int>(k)))
    throw std::invalid_argument("style 'curvature' parameter 'k' must be a whole number");
  CurvatureShadingFunction::parse(params.text("shading_tf"));
  CurvatureOpacityFunction::parse(params.text("opacity_tf"));
}

std::vector<std::unique_ptr<RenderPass>> CurvatureStyle::passes(const StyleParams& params) const {
  const CurvatureStylization stylization = stylizationOf(params);
  std::vector<std::unique_ptr<RenderPass>> p;
  if (stylization != CurvatureStylization::Plain) {
    const auto search = params.is("query", "brute-force") ? kbuffer::NeighborSearch::BruteForce : kbuffer::NeighborSearch::Buckets;
    p.push_back(functionPass("neighbors", [search](FrameContext& f) {
      findBucketNeighbors(f.fillAs<BucketedKBuffer>(), f.shaders, search);
    }));
    const auto scale = static_cast<float>(params.number("scale"));
    p.push_back(functionPass("curvature", [scale](FrameContext& f) {
      computeScreenSpaceCurvature(f.fillAs<BucketedKBuffer>(), f.shaders, scale, f.scene.boundingSphere().radius,
                                  f.raster.projection[1][1]);
    }));
  }
  const auto alpha = static_cast<float>(params.number("alpha"));
  p.push_back(functionPass("compose", [stylization, alpha, shading = CurvatureShadingFunction::parse(params.text("shading_tf")),
                                       opacity = CurvatureOpacityFunction::parse(params.text("opacity_tf"))](FrameContext& f) {
    composeCurvature(f, f.fillAs<BucketedKBuffer>(), stylization, alpha, shading, opacity);
  }));
  return p;
}

}  // namespace tlab::render
