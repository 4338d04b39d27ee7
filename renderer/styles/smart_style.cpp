#include "renderer/styles/smart_style.hpp"

#include "renderer/compose/smart_compositor.hpp"
#include "renderer/ops/connect_pass.hpp"
#include "renderer/ops/diffusion_solver.hpp"
#include "renderer/buffer/fragment_buffer.hpp"

namespace tlab::render {

namespace {

// What the three passes of one frame share.
struct SmartFrame {
  SmartSettings settings;
  bool solves = false;  // whether a solve pass follows the connect pass
  TransparencyFields* fields = nullptr;  // the renderer's, or `own` without one
  std::unique_ptr<TransparencyFields> own;
};

}  // namespace

std::vector<ParamSpec> SmartStyle::params() const {
  // Defaults from Carnecky Fig. 9 (second column) and Sec. 5.4 (λα = 1, 10-50 iterations).
  return {
      ParamSpec::number("iterations", 20, 0, 100000, "diffusion steps n (Sec. 5.4)"),
      ParamSpec::number("lambda_alpha", 1.0, 0, 1e6, "α diffusion coefficient λα (Eq. 8)"),
      ParamSpec::number("lambda_beta", 0.05, 0, 1, "β spreading λβ (Eq. 9)"),
      ParamSpec::number("lambda_gamma", 0.1, 0, 1, "γ spreading λγ (Eq. 9)"),
      ParamSpec::number("s", 0.3, 0, 1, "initial transparency parameter s (Eqs. 4-5)"),
      ParamSpec::choice("alpha_init", "constant", {"constant", "adaptive"}, "initial α: Eq. 4 or Eq. 5"),
      ParamSpec::choice("modifier", "exp", {"none", "exp", "pow"}, "profile modifier of β and γ: Eq. 10 or Eq. 11"),
      ParamSpec::number("p", 3, 1e-6, 1e3, "modifier parameter p (Eqs. 10-11)"),
      ParamSpec::choice("spread", "max", {"max", "diffusion"}, "β/γ spreading: Eq. 9 or Eq. 8"),
      ParamSpec::choice("halos", "on", {"on", "off"}, "the γ field (halos behind occluding edges)"),
      ParamSpec::choice("silhouettes", "on", {"on", "off"}, "the β field (silhouette highlights)"),
      ParamSpec::number("wz", 1, 0, 1e6, "weight of εz in Eq. 3"),
      ParamSpec::number("wn", 1, 0, 1e6, "weight of εn in Eq. 3"),
      ParamSpec::choice("laplacian", "normalized", {"normalized", "sum"},
                        "Eq. 8's Laplacian: mean of the neighbours − α (explicit up to λα = 1) or their sum (up to 1/4)"),
      ParamSpec::choice("solver", "auto", {"auto", "explicit", "substep", "implicit"},
                        "α diffusion scheme: auto (explicit up to the reading's bound, sub-stepped up to 8 sub-steps, implicit beyond), or forced"),
      ParamSpec::number("jacobi_sweeps", 10, 1, 10000, "Jacobi sweeps per implicit step"),
  };
}

void SmartStyle::validate(const StyleParams& params) const { SmartSettings::from(params); }

FragmentProperties SmartStyle::properties(const StyleParams&, const SceneFacts& facts) const {
  FragmentProperties p;
  p |= FragmentProperty::Color;
  p |= FragmentProperty::Normal;
  p |= FragmentProperty::DepthGradient;
  if (facts.componentCount > 1) p |= FragmentProperty::Ids;  // ε = ∞ across components
  return p;
}

std::vector<std::unique_ptr<RenderPass>> SmartStyle::passes(const StyleParams& params) const {
  auto frame = std::make_shared<SmartFrame>();
  frame->settings = SmartSettings::from(params);
  frame->solves =
      frame->settings.iterations > 0 && (frame->settings.diffusesAlpha() || frame->settings.silhouettes || frame->settings.halos);
  std::vector<std::unique_ptr<RenderPass>> p;
  // The links (Alg. 2), initial α and boundary conditions; when no solve pass is scheduled
  // (nothing to diffuse or spread) it notes what was left out.
  p.push_back(std::make_unique<FunctionPass>("connect", [frame](FrameContext& f, std::vector<std::string>& operations) {
    if (!f.fields) frame->own = std::make_unique<TransparencyFields>();
    frame->fields = f.fields ? f.fields : frame->own.get();
    connectFragments(f.fillAs<FragmentBuffer>(), f.shaders, frame->settings, f.scene.boundingSphere().radius, *frame->fields,
                     NeighborSearch::Bounded, ConnectOutput::WhatTheFrameReads, f.timer);
    if (!frame->solves) operations = DiffusionSolver(f.shaders, frame->settings).operations();
  }));
  if (frame->solves)
    p.push_back(std::make_unique<FunctionPass>("solve", [frame](FrameContext& f, std::vector<std::string>& operations) {
      const DiffusionSolver solver(f.shaders, frame->settings);
      solver.solve(*frame->fields, f.timer);
      operations = solver.operations();
    }));
  p.push_back(functionPass("compose", [frame](FrameContext& f) { composeSmart(f, *frame->fields, frame->settings); }));
  return p;
}

}  // namespace tlab::render
