#include "renderer/ops/diffusion_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "renderer/gpu/gl_error.hpp"

namespace tlab::render {

namespace {
constexpr GLuint kFieldIn = 13, kFieldOut = 14;  // BIND_BETA_IN/OUT of ops/field_bindings.glsl
constexpr unsigned kFreeBeta = 2, kFreeGamma = 4;  // also the bits of the change record
constexpr GLuint kChangedBinding = 19;              // BIND_CHANGED
constexpr GLuint kLinks = 10, kFlags = 17;           // BIND_LINKS, BIND_FLAGS
constexpr GLuint kFrontierIn = 23, kFrontierOut = 24;

// The frontier steps' checks (the shader's and the host code's), the full steps' own: after steps
// 1, 2, 4, 8, ... the steps stop where the field has not moved since the last check, so both run
// the steps the full steps run. A step changed the field iff it listed a fragment, and a step after
// one that listed none has nothing to spread from: the field moved since the last check iff the
// first step after it listed something (all a caller is asked for, the shader's count a read-back).
class SettleChecks {
 public:
  bool asksWhetherMoved(int step) const { return step == lastCheck_ + 1; }  // steps 0-based
  void setMoved(bool moved) { movedSinceCheck_ = moved; }
  bool stopsAfter(int step) {
    if ((step & (step + 1)) != 0) return false;
    if (!movedSinceCheck_) return true;
    lastCheck_ = step;
    return false;
  }

 private:
  int lastCheck_ = -1;  // the step of the last check
  bool movedSinceCheck_ = false;
};

void run(const gpu::ShaderProgram& program, std::size_t fragments, double lambda) {
  program.use();  // (callers may have set further uniforms on it already)
  glUniform1ui(program.uniform("uFragments"), static_cast<GLuint>(fragments));
  glUniform1f(program.uniform("uLambda"), static_cast<float>(lambda));
  gpu::dispatchLinear(fragments);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

std::string fixed(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}
}  // namespace

DiffusionSolver::DiffusionSolver(gpu::ShaderCache& shaders, const SmartSettings& settings)
    : settings_(settings),
      shaders_(shaders),
      spreadMax_(&shaders.compute("ops/spread_field.comp", {{"TLAB_SPREAD_MAX", "1"}})),
      spreadDiffusion_(&shaders.compute("ops/spread_field.comp")),
      frontierStep_(&shaders.compute("ops/spread_frontier.comp")),
      frontierStepTexels_(&shaders.compute("ops/spread_frontier.comp", {{"TLAB_FIELD_TEXELS", "1"}})),
      frontierOnHost_(gpu::hostPassesWanted()),
      changed_(sizeof(std::uint32_t)) {}

const gpu::ShaderProgram& DiffusionSolver::alphaProgram(bool jacobi, Spread fused) const {
  gpu::ShaderDefines d;
  if (jacobi) d.emplace_back("TLAB_JACOBI", "1");
  if (!settings_.diffusesAlpha()) d.emplace_back("TLAB_SKIP_ALPHA", "1");
  if (fused.any()) {
    d.emplace_back("TLAB_FUSED_SPREAD", "1");
    if (fused.beta) d.emplace_back("TLAB_HAS_BETA", "1");
    if (fused.gamma) d.emplace_back("TLAB_HAS_GAMMA", "1");
  }
  const auto& program = shaders_.compute("ops/diffuse_alpha.comp", d);
  program.use();
  glUniform1i(program.uniform("uNormalized"), settings_.normalizedLaplacian ? 1 : 0);
  if (fused.any()) {
    glUniform1f(program.uniform("uLambdaBeta"), static_cast<float>(settings_.lambdaBeta));
    glUniform1f(program.uniform("uLambdaGamma"), static_cast<float>(settings_.lambdaGamma));
  }
  return program;
}

int DiffusionSolver::alphaDispatches() const { return settings_.alphaDispatchesPerStep(); }

void DiffusionSolver::diffuseAlpha(TransparencyFields& fields, Spread fused) const {
  const std::size_t n = fields.fragments();
  const double lambda = settings_.lambdaAlpha;
  const Spread none;
  // After the first dispatch of a fused step, β and γ are done: swap them to current.
  const auto afterFirst = [&](bool first) {
    if (!first) return;
    if (fused.beta) fields.swap(Field::Beta);
    if (fused.gamma) fields.swap(Field::Gamma);
  };
  if (!settings_.diffusesAlpha()) {  // α uniform: the spreading alone, in one dispatch
    if (!fused.any()) return;
    fields.bindCurrent();
    run(alphaProgram(false, fused), n, lambda);
    afterFirst(true);
    return;
  }
  if (settings_.scheme == DiffusionScheme::Implicit) {
    // Backward Euler (I + λL)α' = α: keep α in the scratch buffer, Jacobi sweeps from α.
    glCopyNamedBufferSubData(fields.current(Field::Alpha).id(), fields.scratch().id(), 0, 0,
                             static_cast<GLsizeiptr>(n * sizeof(float)));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    for (int sweep = 0; sweep < settings_.jacobiSweeps; ++sweep) {
      fields.bindCurrent();
      run(alphaProgram(true, sweep == 0 ? fused : none), n, lambda);
      fields.swap(Field::Alpha);
      afterFirst(sweep == 0);
    }
    return;
  }
  // Explicit (λ within the bound) or sub-stepped: m steps of λ/m cover the same diffusion time λ.
  const int m = alphaDispatches();
  for (int k = 0; k < m; ++k) {
    fields.bindCurrent();
    run(alphaProgram(false, k == 0 ? fused : none), n, lambda / m);
    fields.swap(Field::Alpha);
    afterFirst(k == 0);
  }
}

void DiffusionSolver::spread(TransparencyFields& fields, Field field, double lambda, unsigned freeBit) const {
  const std::size_t n = fields.fragments();
  const int m = settings_.spreadByMax ? 1 : substepsFor(lambda, kExplicitStableLambdaSum);
  for (int k = 0; k < m; ++k) {
    fields.bindPair(field, kFieldIn, kFieldOut);
    const auto& program = settings_.spreadByMax ? *spreadMax_ : *spreadDiffusion_;
    program.use();
    glUniform1ui(program.uniform("uFreeBit"), freeBit);
    run(program, n, settings_.spreadByMax ? lambda : lambda / m);
    fields.swap(field);
  }
}

void DiffusionSolver::step(TransparencyFields& fields) const {
  fields.setSeedsListed(false);  // β and γ move past their seeds
  step(fields, {fields.hasBeta(), fields.hasGamma()});
}

void DiffusionSolver::step(TransparencyFields& fields, Spread spread) const {
  if (fields.fragments() == 0) return;
  // Eq. 9 spreading rides along with the first α dispatch; Eq. 8 spreading needs its own passes.
  diffuseAlpha(fields, settings_.spreadByMax ? spread : Spread{});
  if (!settings_.spreadByMax) {
    if (spread.beta) this->spread(fields, Field::Beta, settings_.lambdaBeta, kFreeBeta);
    if (spread.gamma) this->spread(fields, Field::Gamma, settings_.lambdaGamma, kFreeGamma);
  }
  gpu::checkGl("the diffusion solver");
}

// Eq. 9 settles after ⌈1/λ⌉ steps: a value carried over a longer path is 1 − λ·length ≤ 0, and
// fields never drop below 0. Steps beyond that change nothing and are left out (λ = 0 never settles).
int DiffusionSolver::spreadSteps(double lambda) const {
  if (!settings_.spreadByMax || lambda <= 0) return settings_.iterations;
  return std::min(settings_.iterations, static_cast<int>(std::ceil(1.0 / lambda - 1e-9)));
}

// Whether a fused step changed β (bit 2) or γ (bit 4) anywhere; clears the record for the next.
unsigned DiffusionSolver::takeChanges() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::uint32_t bits = 0;
  changed_.download(&bits, sizeof bits);
  changed_.clearToZero();
  return bits;
}

// Eq. 9 steps on the frontier only (ops/spread_frontier.comp), from the seeds the connect pass
// listed: per step one pass has each fragment the previous step raised offer its value minus λ
// to its neighbours and lists those it raises. The field's two copies take turns: a step reads
// one and raises the other. Stops as the full steps do.
int DiffusionSolver::spreadFrontier(TransparencyFields& fields, Field field, double lambda, int steps,
                                    unsigned freeBit, PassTimer* timer) const {
  const gpu::Buffer* previous = &fields.frontier(field);  // step 1: the seeds
  const gpu::Buffer* changed = &fields.frontier(Field::Alpha);
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT);  // the connect pass wrote the seed list's header
  // Without seeds the first step changes nothing, and the full steps stop after it: so do these,
  // without copying the field (the 16-layer stack has 4 M fragments and no seed).
  if (fields.allZero(field)) return 1;
  // Both copies start as the current values (see ops/spread_frontier.comp for why a copy two
  // steps old is enough for the step that raises it).
  const std::size_t n = fields.fragments();
  glCopyNamedBufferSubData(fields.current(field).id(), fields.output(field).id(), 0, 0, GLsizeiptr(n * sizeof(float)));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  fields.links().bindBase(GL_SHADER_STORAGE_BUFFER, kLinks);
  fields.flags().bindBase(GL_SHADER_STORAGE_BUFFER, kFlags);
  // Where the GL allows that many texels, the step reads links, flags and the field through
  // buffer textures (units 0-3; TLAB_FIELD_TEXELS), else through the storage buffers.
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  const bool texels = fieldTexels_ && double(n) <= double(maxTexels);
  const auto view = [&](const gpu::Buffer& b, GLenum format, std::size_t bytes, GLuint unit) {
    return texels ? gpu::bindBufferTexture(b.id(), format, bytes, unit) : gpu::Texture{};
  };
  const gpu::Texture links = view(fields.links(), GL_RGBA32UI, n * 16, 0);
  const gpu::Texture flags = view(fields.flags(), GL_R32UI, n * 4, 1);
  // The values of either copy, read in turns (units 2 and 3).
  const gpu::Texture values[2] = {view(fields.current(field), GL_R32F, n * 4, 2),
                                  view(fields.output(field), GL_R32F, n * 4, 3)};
  const gpu::ShaderProgram& stepProgram = texels ? *frontierStepTexels_ : *frontierStep_;
  stepProgram.use();
  if (texels) {
    glUniform1i(stepProgram.uniform("uLinks"), 0);
    glUniform1i(stepProgram.uniform("uFlags"), 1);
  }
  glUniform1f(stepProgram.uniform("uLambda"), static_cast<float>(lambda));
  glUniform1ui(stepProgram.uniform("uFreeBit"), freeBit);
  int run = 0;
  bool raisedOutput = false;  // whether the last step raised the output copy
  SettleChecks checks;
  for (int i = 0; i < steps; ++i) {
    const bool readCurrent = i % 2 == 0;  // step 1 reads the current copy and raises the other
    (readCurrent ? fields.current(field) : fields.output(field)).bindBase(GL_SHADER_STORAGE_BUFFER, kFieldIn);
    (readCurrent ? fields.output(field) : fields.current(field)).bindBase(GL_SHADER_STORAGE_BUFFER, kFieldOut);
    TransparencyFields::clearList(*changed);
    previous->bindBase(GL_SHADER_STORAGE_BUFFER, kFrontierIn);
    changed->bindBase(GL_SHADER_STORAGE_BUFFER, kFrontierOut);
    stepProgram.use();
    if (texels) glUniform1i(stepProgram.uniform("uValues"), readCurrent ? 2 : 3);
    timePart(timer, field == Field::Beta ? "solve beta frontier step" : "solve gamma frontier step",
             [&] { TransparencyFields::dispatchOnList(stepProgram, *previous); });
    raisedOutput = readCurrent;
    ++run;
    if (checks.asksWhetherMoved(i)) checks.setMoved(fields.listCount(*changed) > 0);
    if (checks.stopsAfter(i)) break;
    std::swap(previous, changed);
  }
  if (raisedOutput) fields.swap(field);
  gpu::checkGl("ops/spread_frontier.comp");
  return run;
}

// The steps of spreadFrontier (ops/spread_frontier.comp explains them) as host code: the links
// and flags mapped, the field read once, raised in place and written back once. A step first
// takes the values of the fragments the last step changed (u_j after step t − 1), then has each
// offer u_j − λ_u to its free neighbours (Eq. 9): a neighbour f is raised where the offer exceeds
// its value so far and listed for the next step the first time this step raises it — the offers
// that exceed u_f after step t − 1, as the shader's atomic maxima list it. The same float
// subtraction and maxima, so the same fields bit for bit, and the same checks, so the same steps.
int DiffusionSolver::spreadFrontierOnHost(TransparencyFields& fields, Field field, double lambda, int steps,
                                          unsigned freeBit) const {
  if (fields.allZero(field)) return 1;  // as spreadFrontier: no seed, one step that changes nothing
  constexpr std::uint32_t kNoNeighbor = 0xFFFFFFFFu;  // NO_NEIGHBOR of ops/field_bindings.glsl
  const std::size_t n = fields.fragments();
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // the connect pass's (and set_listed.comp's) writes, for the host
  std::vector<std::uint32_t> previous = fields.readList(field), changed;  // step 1: the seeds
  std::vector<float> u(n);
  fields.current(field).download(u.data(), n * sizeof(float));
  const gpu::MappedRead linkWords(fields.links(), n * sizeof(glm::uvec4)), flagWords(fields.flags(), n * 4);
  const auto* links = linkWords.as<glm::uvec4>();
  const auto* flags = flagWords.as<std::uint32_t>();
  const float lambdaF = static_cast<float>(lambda);
  std::vector<std::uint8_t> raised(n, 0);  // raised in this step (cleared from `changed` after it)
  std::vector<float> offers;
  int run = 0;
  bool moved = false;
  SettleChecks checks;
  for (int i = 0; i < steps; ++i) {
    offers.resize(previous.size());
    for (std::size_t k = 0; k < previous.size(); ++k) offers[k] = u[previous[k]] - lambdaF;  // Eq. 9's u_j − λ_u
    changed.clear();
    for (std::size_t k = 0; k < previous.size(); ++k) {
      const glm::uvec4 around = links[previous[k]];
      const float offer = offers[k];
      for (int e = 0; e < 4; ++e) {
        const std::uint32_t f = around[e];
        if (f == kNoNeighbor || (flags[f] & freeBit) == 0u || !(offer > u[f])) continue;
        u[f] = offer;
        if (!raised[f]) raised[f] = 1, changed.push_back(f);
      }
    }
    for (const std::uint32_t f : changed) raised[f] = 0;
    moved = moved || !changed.empty();
    ++run;
    if (checks.asksWhetherMoved(i)) checks.setMoved(!changed.empty());
    if (checks.stopsAfter(i)) break;
    std::swap(previous, changed);
  }
  if (moved) fields.current(field).upload(u.data(), n * sizeof(float));
  return run;
}

void DiffusionSolver::solve(TransparencyFields& fields, PassTimer* timer) const {
  const int betaSteps = fields.hasBeta() ? spreadSteps(settings_.lambdaBeta) : 0;
  const int gammaSteps = fields.hasGamma() ? spreadSteps(settings_.lambdaGamma) : 0;
  betaRun_ = gammaRun_ = 0;
  if (fields.takeSeedsListed() && settings_.spreadByMax && fields.fragments() > 0) {
    // The connect pass listed Eq. 9's seeds: α diffuses alone (if at all), β and γ spread on
    // their frontiers — the fields of the full steps below, bit for bit.
    for (int i = 0; settings_.diffusesAlpha() && i < settings_.iterations; ++i)
      timePart(timer, "solve alpha step", [&] { step(fields, Spread{}); });
    const auto spreadOne = [&](Field field, double lambda, int steps, unsigned freeBit) {
      if (!frontierOnHost_) return spreadFrontier(fields, field, lambda, steps, freeBit, timer);
      int run = 0;
      timePart(timer, field == Field::Beta ? "solve beta frontier on the host" : "solve gamma frontier on the host",
               [&] { run = spreadFrontierOnHost(fields, field, lambda, steps, freeBit); });
      return run;
    };
    if (betaSteps > 0) betaRun_ = spreadOne(Field::Beta, settings_.lambdaBeta, betaSteps, kFreeBeta);
    if (gammaSteps > 0) gammaRun_ = spreadOne(Field::Gamma, settings_.lambdaGamma, gammaSteps, kFreeGamma);
    return;
  }
  bool betaMoves = true, gammaMoves = true;  // false once a step left the field as it was
  changed_.clearToZero();
  changed_.bindBase(GL_SHADER_STORAGE_BUFFER, kChangedBinding);
  for (int i = 0; i < settings_.iterations; ++i) {
    const Spread spread{betaMoves && i < betaSteps, gammaMoves && i < gammaSteps};
    if (!settings_.diffusesAlpha() && !spread.any()) break;
    timePart(timer, "solve step", [&] { step(fields, spread); });
    betaRun_ += spread.beta ? 1 : 0;
    gammaRun_ += spread.gamma ? 1 : 0;
    // A step that changes nothing is a fixed point of Eq. 9: the next would not change it either.
    // Checked after steps 1, 2, 4, 8, ... (each check waits for the GPU).
    if (settings_.spreadByMax && spread.any() && (i & (i + 1)) == 0) {
      const unsigned bits = takeChanges();
      betaMoves = betaMoves && (!spread.beta || (bits & kFreeBeta) != 0);
      gammaMoves = gammaMoves && (!spread.gamma || (bits & kFreeGamma) != 0);
    }
  }
}

int DiffusionSolver::dispatchesPerStep() const {
  const int alpha = alphaDispatches();
  if (settings_.spreadByMax) return alpha > 0 ? alpha : (settings_.silhouettes || settings_.halos ? 1 : 0);
  return alpha + (settings_.silhouettes ? substepsFor(settings_.lambdaBeta, kExplicitStableLambdaSum) : 0) +
         (settings_.halos ? substepsFor(settings_.lambdaGamma, kExplicitStableLambdaSum) : 0);
}

std::vector<std::string> DiffusionSolver::operations() const {
  std::vector<std::string> ops;
  const std::string n = std::to_string(settings_.iterations) + " steps";
  if (!settings_.diffusesAlpha()) {
    ops.push_back("alpha diffusion skipped (" + std::string(settings_.iterations > 0 && settings_.lambdaAlpha > 0
                                                                  ? "initial alpha uniform: alpha_init=constant"
                                                                  : "no diffusion time") + ")");
  } else {
    const char* scheme = settings_.scheme == DiffusionScheme::Implicit ? "implicit"
                         : settings_.scheme == DiffusionScheme::Explicit ? "explicit"
                                                                         : "substep";
    ops.push_back("alpha diffusion (Eq. 8, " + std::string(settings_.normalizedLaplacian ? "normalized" : "sum") +
                  " Laplacian, " + scheme + ", lambda " + fixed(settings_.lambdaAlpha) + ", " + n + ", " +
                  std::to_string(alphaDispatches()) + " dispatch(es) per step)");
  }
  const std::string how = settings_.spreadByMax ? "Eq. 9 max" : "Eq. 8 diffusion";
  // Steps run (after a solve) or planned, of the n asked for.
  const auto steps = [&](double lambda, int run) {
    const int k = run >= 0 ? run : spreadSteps(lambda);
    if (k == settings_.iterations) return n;
    return std::to_string(k) + " of " + n + ": settled" + (run >= 0 ? "" : " after 1/lambda");
  };
  if (settings_.silhouettes) ops.push_back("beta spreading (" + how + ", " + steps(settings_.lambdaBeta, betaRun_) + ")");
  if (settings_.halos) ops.push_back("gamma spreading (" + how + ", " + steps(settings_.lambdaGamma, gammaRun_) + ")");
  if (!settings_.halos) ops.push_back("gamma skipped (halos=off)");
  if (!settings_.silhouettes) ops.push_back("beta skipped (silhouettes=off)");
  return ops;
}

}  // namespace tlab::render
