#include "renderer/ops/connect_pass.hpp"

#include "renderer/buffer/fragment_layout.hpp"
#include "renderer/gpu/gl_error.hpp"

namespace tlab::render {

std::unique_ptr<TransparencyFields> connectFragments(const FragmentBuffer& buffer, gpu::ShaderCache& shaders,
                                                     const SmartSettings& settings, float objectRadius,
                                                     NeighborSearch search) {
  auto fields = std::make_unique<TransparencyFields>(buffer.fragmentCount(), settings.silhouettes, settings.halos);
  gpu::ShaderDefines defines = buffer.layout().defines();
  for (const auto& d : fields->defines()) defines.push_back(d);
  if (search == NeighborSearch::AllPairs) defines.emplace_back("TLAB_ALL_PAIRS", "1");
  buffer.bindSorted();
  fields->bindCurrent();
  for (const char* phase : {"1", "2"}) {
    gpu::ShaderDefines phaseDefines = defines;
    phaseDefines.emplace_back("TLAB_PHASE", phase);
    const auto& program = shaders.compute("ops/connect.comp", phaseDefines);
    program.use();
    glUniform1i(program.uniform("uWidth"), buffer.width());
    glUniform1i(program.uniform("uHeight"), buffer.height());
    glUniform1f(program.uniform("uObjectRadius"), objectRadius);
    glUniform1f(program.uniform("uWz"), float(settings.wz));
    glUniform1f(program.uniform("uWn"), float(settings.wn));
    glUniform1f(program.uniform("uS"), float(settings.s));
    glUniform1i(program.uniform("uAdaptiveAlpha"), settings.adaptiveAlpha ? 1 : 0);
    gpu::dispatchLinear(buffer.pixels());
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  }
  // The pass wrote every field's output copy: make those current.
  fields->swap(Field::Alpha);
  if (fields->hasBeta()) fields->swap(Field::Beta);
  if (fields->hasGamma()) fields->swap(Field::Gamma);
  gpu::checkGl("ops/connect.comp");
  return fields;
}

}  // namespace tlab::render
