#include "renderer/compose/smart_compositor.hpp"

#include <optional>
#include <string>

#include "renderer/buffer/fragment_buffer.hpp"

namespace tlab::render {

void composeSmart(FrameContext& frame, const TransparencyFields& fields, const SmartSettings& settings) {
  const FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  // What the compose reads of the fields: β and γ where they may be above 0 (a field that is 0
  // everywhere adds nothing: modifier(0) = 0), α where it varies (Eq. 4's α is s everywhere).
  // (The compose binds only the fields it reads: a field the connect pass left unstored is then
  // never written out, TransparencyFields::setUniform.)
  gpu::ShaderDefines defines = buffer.layout().defines();
  const bool readsBeta = fields.hasBeta() && !fields.allZero(Field::Beta);
  const bool readsGamma = fields.hasGamma() && !fields.allZero(Field::Gamma);
  const std::optional<float> uniformAlpha = fields.uniformValue(Field::Alpha);
  if (readsBeta) defines.emplace_back("TLAB_HAS_BETA", "1");
  if (readsGamma) defines.emplace_back("TLAB_HAS_GAMMA", "1");
  if (uniformAlpha) defines.emplace_back("TLAB_UNIFORM_ALPHA", "1");
  defines.emplace_back("TLAB_MODIFIER", std::to_string(settings.modifier));
  // The colours from the sort's colour plane where it wrote one (SmartStyle::fill asks for it).
  if (buffer.colorPlane()) defines.emplace_back("TLAB_COLOR_PLANE", "1");
  const auto& program = frame.shaders.compute("compose/smart_compose.comp", defines);
  const gpu::Buffer& output = buffer.composeOutput();
  buffer.bindSorted();
  constexpr unsigned kAlphaIn = 11, kBetaIn = 13, kGammaIn = 15;  // BIND_*_IN of ops/field_bindings.glsl
  if (!uniformAlpha) fields.bindInput(Field::Alpha, kAlphaIn);
  if (readsBeta) fields.bindInput(Field::Beta, kBetaIn);
  if (readsGamma) fields.bindInput(Field::Gamma, kGammaIn);
  // A pixel without fragments composes to c + T·c_background with c = 0, T = 1: the background,
  // exactly. The buffer is cleared to it, and the shader runs for the pixels with fragments only.
  const glm::vec4 background(glm::vec3(frame.background), 1.0f);
  glClearNamedBufferData(output.id(), GL_RGBA32F, GL_RGBA, GL_FLOAT, &background[0]);
  output.bindBase(GL_SHADER_STORAGE_BUFFER, 9);  // BIND_OUTPUT
  program.use();
  glUniform4fv(program.uniform("uBackground"), 1, &frame.background[0]);
  glUniform1f(program.uniform("uP"), static_cast<float>(settings.p));
  if (uniformAlpha) glUniform1f(program.uniform("uS"), *uniformAlpha);
  buffer.dispatchCovered(program);
  finishCompose(frame, output, "compose/smart_compose.comp");
}

}  // namespace tlab::render
