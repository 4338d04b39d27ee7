#include "renderer/ops/diffusion_solver.hpp"

#include "renderer/gpu/gl_error.hpp"

namespace tlab::render {

namespace {
constexpr GLuint kAlphaIn = 11, kAlphaOut = 12, kFieldIn = 13, kFieldOut = 14;  // ops/field_bindings.glsl
constexpr unsigned kFreeBeta = 2, kFreeGamma = 4;

void run(const gpu::ShaderProgram& program, std::size_t fragments, double lambda) {
  program.use();
  glUniform1ui(program.uniform("uFragments"), static_cast<GLuint>(fragments));
  glUniform1f(program.uniform("uLambda"), static_cast<float>(lambda));
  gpu::dispatchLinear(fragments);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}
}  // namespace

DiffusionSolver::DiffusionSolver(gpu::ShaderCache& shaders, const SmartSettings& settings)
    : settings_(settings),
      explicitStep_(&shaders.compute("ops/diffuse_alpha.comp")),
      jacobiSweep_(&shaders.compute("ops/diffuse_alpha.comp", {{"TLAB_JACOBI", "1"}})),
      spreadMax_(&shaders.compute("ops/spread_field.comp", {{"TLAB_SPREAD_MAX", "1"}})),
      spreadDiffusion_(&shaders.compute("ops/spread_field.comp")) {}

void DiffusionSolver::diffuseAlpha(TransparencyFields& fields) const {
  const std::size_t n = fields.fragments();
  const double lambda = settings_.lambdaAlpha;
  if (settings_.scheme == DiffusionScheme::Implicit) {
    // Backward Euler (I + λL)α' = α: keep α in the scratch buffer, Jacobi sweeps from α.
    glCopyNamedBufferSubData(fields.current(Field::Alpha).id(), fields.scratch().id(), 0, 0,
                             static_cast<GLsizeiptr>(n * sizeof(float)));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    for (int sweep = 0; sweep < settings_.jacobiSweeps; ++sweep) {
      fields.bindPair(Field::Alpha, kAlphaIn, kAlphaOut);
      run(*jacobiSweep_, n, lambda);
      fields.swap(Field::Alpha);
    }
    return;
  }
  // Explicit (λ ≤ 1/4) or sub-stepped: m steps of λ/m cover the same diffusion time λ.
  const int m = settings_.scheme == DiffusionScheme::Explicit ? 1 : substepsFor(lambda);
  for (int k = 0; k < m; ++k) {
    fields.bindPair(Field::Alpha, kAlphaIn, kAlphaOut);
    run(*explicitStep_, n, lambda / m);
    fields.swap(Field::Alpha);
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
  fields.bindCurrent();  // links and flags
  diffuseAlpha(fields);
  if (fields.hasBeta()) spread(fields, Field::Beta, settings_.lambdaBeta, kFreeBeta);
  if (fields.hasGamma()) spread(fields, Field::Gamma, settings_.lambdaGamma, kFreeGamma);
  gpu::checkGl("the diffusion solver");
}

void DiffusionSolver::solve(TransparencyFields& fields) const {
  for (int i = 0; i < settings_.iterations; ++i) step(fields);
}

int DiffusionSolver::dispatchesPerStep() const {
  const int alpha = settings_.scheme == DiffusionScheme::Implicit ? settings_.jacobiSweeps
                    : settings_.scheme == DiffusionScheme::Explicit ? 1
                                                                    : substepsFor(settings_.lambdaAlpha);
  const auto spreadCount = [&](double l) { return settings_.spreadByMax ? 1 : substepsFor(l); };
  return alpha + (settings_.silhouettes ? spreadCount(settings_.lambdaBeta) : 0) +
         (settings_.halos ? spreadCount(settings_.lambdaGamma) : 0);
}

}  // namespace tlab::render
