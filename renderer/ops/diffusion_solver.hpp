#pragma once
// The solve pass (Carnecky Sec. 5.4): n steps of α diffusion (Eq. 8; explicit, sub-stepped or
// implicit — see ops/diffuse_alpha.comp for the stability bound) and β/γ spreading (Eq. 9 or
// Eq. 8), each step a ping-pong compute pass over all fragments — or, for Eq. 9 from the seeds
// the connect pass listed, passes over the frontier only (ops/spread_frontier.comp). What a scene does not need is
// left out: no α diffusion when α starts uniform (Eq. 4), no γ with halos off, no β without
// silhouettes.
#include <string>
#include <vector>

#include "renderer/frame/pass_timer.hpp"
#include "renderer/gpu/shader_cache.hpp"
#include "renderer/ops/smart_settings.hpp"
#include "renderer/ops/transparency_fields.hpp"

namespace tlab::render {

class DiffusionSolver {
 public:
  DiffusionSolver(gpu::ShaderCache& shaders, const SmartSettings& settings);
  // One of the n steps (time λα) on all fields.
  void step(TransparencyFields& fields) const;
  // The n steps; β and γ spreading by Eq. 9 stop once they have settled (⌈1/λ⌉ steps, or a
  // step that changed nothing). Where the connect pass listed Eq. 9's seeds for these fields
  // (and nothing changed them since), β and γ spread on the frontier only
  // (ops/spread_frontier.comp): the same fields, bit for bit, for a fraction of the work. With a
  // timer, each step is a part of the running pass ("solve step", or "solve alpha step" and
  // "solve beta|gamma frontier step").
  void solve(TransparencyFields& fields, PassTimer* timer = nullptr) const;
  // Dispatches this solver makes per step (for the statistics and the benchmark).
  int dispatchesPerStep() const;
  // What the solve does and leaves out (for --stats-json): one line per field, with the steps
  // the last solve() ran (before any solve: the steps planned).
  std::vector<std::string> operations() const;
  // Whether a solve has anything to do (α to diffuse or β/γ to spread).
  bool hasWork() const { return settings_.iterations > 0 && dispatchesPerStep() > 0; }
  // The frontier steps read links, flags and the field as buffer textures where the GL allows
  // that many texels (on), or always as storage buffers (off): the same fields (tests compare).
  void setFieldTexels(bool on) { fieldTexels_ = on; }
  // The frontier steps run as host code over the mapped links, flags and field (on), or as
  // ops/spread_frontier.comp (off): the same fields and steps, bit for bit (tests compare). The
  // default is gpu::hostPassesWanted(): on where the GL runs on the CPU, where a step's few
  // thousand scattered reads and atomic maxima cost more as a shader run lane by lane than as a
  // loop (issue #29: the torus's 20 steps 5–6 ms as the shader, 1.3–1.9 ms as host code).
  void setFrontierOnHost(bool on) { frontierOnHost_ = on; }
  bool frontierOnHost() const { return frontierOnHost_; }

 private:
  // Which of β and γ a step spreads.
  struct Spread {
    bool beta = false, gamma = false;
    bool any() const { return beta || gamma; }
  };
  void step(TransparencyFields& fields, Spread spread) const;
  // α diffusion for one step; the first dispatch also spreads the fields of `fused` (Eq. 9).
  void diffuseAlpha(TransparencyFields& fields, Spread fused) const;
  int alphaDispatches() const;  // per step; 0 when α cannot change
  int spreadSteps(double lambda) const;  // steps after which Eq. 9 spreading changes nothing
  const gpu::ShaderProgram& alphaProgram(bool jacobi, Spread fused) const;
  unsigned takeChanges() const;
  void spread(TransparencyFields& fields, Field field, double lambda, unsigned freeBit) const;
  // Up to `steps` Eq. 9 steps of `field` from its listed seeds; returns the steps run.
  int spreadFrontier(TransparencyFields& fields, Field field, double lambda, int steps, unsigned freeBit,
                     PassTimer* timer) const;
  // The same steps as host code (setFrontierOnHost).
  int spreadFrontierOnHost(TransparencyFields& fields, Field field, double lambda, int steps, unsigned freeBit) const;

  SmartSettings settings_;
  gpu::ShaderCache& shaders_;
  const gpu::ShaderProgram* spreadMax_;
  const gpu::ShaderProgram* spreadDiffusion_;
  const gpu::ShaderProgram* frontierStep_;
  const gpu::ShaderProgram* frontierStepTexels_;  // reading links, flags and the field as buffer textures
  bool fieldTexels_ = true;
  bool frontierOnHost_;
  mutable gpu::Buffer changed_;  // the fused spreading's change record (BIND_CHANGED)
  mutable int betaRun_ = -1, gammaRun_ = -1;  // steps the last solve spread each field (-1: none yet)
};

}  // namespace tlab::render
