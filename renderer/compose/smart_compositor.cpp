#include "renderer/compose/smart_compositor.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "renderer/buffer/fragment_buffer.hpp"
#include "renderer/compose/blend_compositor.hpp"
#include "renderer/gpu/gl_error.hpp"

namespace tlab::render {

namespace {

// Eq. 10 or 11 of each fragment's value of `field`, as compose/smart_compose.comp computes it.
// Without a modifier that is the clamp to [0, 1], done here. Otherwise the values above 0 (and one
// 0, for all the others: the modifier of a value clamped to 0) go in a list through
// compose/modify_profile.comp, the shader's own function, and come back in the same order.
std::vector<float> modifiedProfile(FrameContext& frame, TransparencyFields& fields, Field field, const SmartSettings& settings) {
  const std::size_t n = fields.fragments();
  std::vector<float> out(n);
  const gpu::MappedRead mapped(fields.current(field), n * 4);
  const float* const values = mapped.as<float>();
  if (settings.modifier == 0) {
    for (std::size_t f = 0; f < n; ++f) out[f] = std::clamp(values[f], 0.0f, 1.0f);
    return out;
  }
  gpu::Buffer& list = fields.scratch();  // n floats: the listed values, then a 0 if some value is not listed
  std::size_t listed = 0;
  {
    const gpu::MappedWrite write(list, n * 4);
    float* const words = write.as<float>();
    for (std::size_t f = 0; f < n; ++f)
      if (values[f] > 0.0f) words[listed++] = values[f];
    if (listed < n) words[listed] = 0.0f;
  }
  const std::size_t count = listed + (listed < n ? 1 : 0);
  const auto& program = frame.shaders.compute("compose/modify_profile.comp", {{"TLAB_MODIFIER", std::to_string(settings.modifier)}});
  program.use();
  glUniform1f(program.uniform("uP"), static_cast<float>(settings.p));
  glUniform1ui(program.uniform("uCount"), static_cast<GLuint>(count));
  list.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  gpu::dispatchLinear(count);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const gpu::MappedRead modified(list, count * 4);
  const float* const m = modified.as<float>();
  const float atZero = listed < n ? m[listed] : 0.0f;
  for (std::size_t f = 0, k = 0; f < n; ++f) out[f] = values[f] > 0.0f ? m[k++] : atZero;
  gpu::checkGl("compose/modify_profile.comp");
  return out;
}

// Alg. 3 as host code over the colour plane the host sort wrote (compose/host_blend.hpp).
void composeSmartOnHost(FrameContext& frame, TransparencyFields& fields, const SmartSettings& settings, bool readsBeta,
                        bool readsGamma, std::optional<float> uniformAlpha) {
  const FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  const std::vector<float> beta = readsBeta ? modifiedProfile(frame, fields, Field::Beta, settings) : std::vector<float>();
  const std::vector<float> gamma = readsGamma ? modifiedProfile(frame, fields, Field::Gamma, settings) : std::vector<float>();
  std::optional<gpu::MappedRead> alpha;
  if (!uniformAlpha) alpha.emplace(fields.current(Field::Alpha), fields.fragments() * 4);
  blendColourPlaneOnHost(frame, buffer, PixelRect{0, 0, buffer.width(), buffer.height()},
                         uniformAlpha ? std::clamp(*uniformAlpha, 0.0f, 1.0f) : 0.0f, alpha ? alpha->as<float>() : nullptr,
                         readsBeta ? beta.data() : nullptr, readsGamma ? gamma.data() : nullptr);
}

}  // namespace

void composeSmart(FrameContext& frame, TransparencyFields& fields, const SmartSettings& settings) {
  const FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  // What the compose reads of the fields: β and γ where they may be above 0 (a field that is 0
  // everywhere adds nothing: modifier(0) = 0), α where it varies (Eq. 4's α is s everywhere).
  // (The compose binds only the fields it reads: a field the connect pass left unstored is then
  // never written out, TransparencyFields::setUniform.)
  const bool readsBeta = fields.hasBeta() && !fields.allZero(Field::Beta);
  const bool readsGamma = fields.hasGamma() && !fields.allZero(Field::Gamma);
  const std::optional<float> uniformAlpha = fields.uniformValue(Field::Alpha);
  if (buffer.colorPlane() && buffer.sortsOnHost()) {  // the host sorted the colours: blend them there too
    composeSmartOnHost(frame, fields, settings, readsBeta, readsGamma, uniformAlpha);
    return;
  }
  gpu::ShaderDefines defines = buffer.layout().defines();
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
