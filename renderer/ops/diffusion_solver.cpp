#include "renderer/ops/diffusion_solver.hpp"

#include "renderer/gpu/gl_error.hpp"

namespace tlab::render {

namespace {
constexpr GLuint kFieldIn = 13, kFieldOut = 14;  // BIND_BETA_IN/OUT of ops/field_bindings.glsl
constexpr unsigned kFreeBeta = 2, kFreeGamma = 4;

void run(const gpu::ShaderProgram& program, std::size_t fragments, double lambda) {
  program.use();  // (callers may have set further uniforms on it already)
  glUniform1ui(program.uniform("uFragments"), static_cast<GLuint>(fragments));
  glUniform1f(program.uniform("uLambda"), static_cast<float>(lambda));
  gpu::dispatchLinear(fragments);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}
}  // namespace

DiffusionSolver::DiffusionSolver(gpu::ShaderCache& shaders, const SmartSettings& settings)
    : settings_(settings),
      shaders_(shaders),
      spreadMax_(&shaders.compute("ops/spread_field.comp", {{"TLAB_SPREAD_MAX", "1"}})),
      spreadDiffusion_(&shaders.compute("ops/spread_field.comp")) {}

const gpu::ShaderProgram& DiffusionSolver::alphaProgram(bool jacobi, bool fused, const TransparencyFields& fields) const {
  gpu::ShaderDefines d;
  if (jacobi) d.emplace_back("TLAB_JACOBI", "1");
  if (fused) {
    d.emplace_back("TLAB_FUSED_SPREAD", "1");
    for (const auto& f : fields.defines()) d.push_back(f);
  }
  const auto& program = shaders_.compute("ops/diffuse_alpha.comp", d);
  if (fused) {
    program.use();
    glUniform1f(program.uniform("uLambdaBeta"), static_cast<float>(settings_.lambdaBeta));
    glUniform1f(program.uniform("uLambdaGamma"), static_cast<float>(settings_.lambdaGamma));
  }
  return program;
}

void DiffusionSolver::diffuseAlpha(TransparencyFields& fields, bool fusedSpread) const {
  const std::size_t n = fields.fragments();
  const double lambda = settings_.lambdaAlpha;
  // After the first dispatch of a fused step, β and γ are done: swap them to current.
  const auto afterFirst = [&](bool first) {
    if (!(first && fusedSpread)) return;
    if (fields.hasBeta()) fields.swap(Field::Beta);
    if (fields.hasGamma()) fields.swap(Field::Gamma);
  };
  if (settings_.scheme == DiffusionScheme::Implicit) {
    // Backward Euler (I + λL)α' = α: keep α in the scratch buffer, Jacobi sweeps from α.
    glCopyNamedBufferSubData(fields.current(Field::Alpha).id(), fields.scratch().id(), 0, 0,
                             static_cast<GLsizeiptr>(n * sizeof(float)));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    for (int sweep = 0; sweep < settings_.jacobiSweeps; ++sweep) {
      fields.bindCurrent();
      run(alphaProgram(true, fusedSpread && sweep == 0, fields), n, lambda);
      fields.swap(Field::Alpha);
      afterFirst(sweep == 0);
    }
    return;
  }
  // Explicit (λ ≤ 1/4) or sub-stepped: m steps of λ/m cover the same diffusion time λ.
  const int m = settings_.scheme == DiffusionScheme::Explicit ? 1 : substepsFor(lambda);
  for (int k = 0; k < m; ++k) {
    fields.bindCurrent();
    run(alphaProgram(false, fusedSpread && k == 0, fields), n, lambda / m);
    fields.swap(Field::Alpha);
    afterFirst(k == 0);
  }
}

void DiffusionSolver::spread(TransparencyFields& fields, Field field, double lambda, unsigned freeBit) const {
  const std::size_t n = fields.fragments();
  const int m = settings_.spreadByMax ? 1 : substepsFor(lambda);
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
  if (fields.fragments() == 0) return;
  // Eq. 9 spreading rides along with the first α dispatch; Eq. 8 spreading needs its own passes.
  const bool fused = settings_.spreadByMax && (fields.hasBeta() || fields.hasGamma());
  diffuseAlpha(fields, fused);
  if (!fused) {
    if (fields.hasBeta()) spread(fields, Field::Beta, settings_.lambdaBeta, kFreeBeta);
    if (fields.hasGamma()) spread(fields, Field::Gamma, settings_.lambdaGamma, kFreeGamma);
  }
  gpu::checkGl("the diffusion solver");
}

void DiffusionSolver::solve(TransparencyFields& fields) const {
  for (int i = 0; i < settings_.iterations; ++i) step(fields);
}

int DiffusionSolver::dispatchesPerStep() const {
  const int alpha = settings_.scheme == DiffusionScheme::Implicit ? settings_.jacobiSweeps
                    : settings_.scheme == DiffusionScheme::Explicit ? 1
                                                                    : substepsFor(settings_.lambdaAlpha);
  if (settings_.spreadByMax) return alpha;  // fused into the first α dispatch
  return alpha + (settings_.silhouettes ? substepsFor(settings_.lambdaBeta) : 0) +
         (settings_.halos ? substepsFor(settings_.lambdaGamma) : 0);
}

}  // namespace tlab::render
