#include "renderer/compose/dynamic_compositor.hpp"

#include "renderer/gpu/gl_error.hpp"
#include "renderer/buffer/fragment_buffer.hpp"

namespace tlab::render {

namespace {
// Binding points of compose/dynamic_surfaces.glsl, dynamic_coverage.comp and dynamic_compose.comp.
constexpr GLuint kBindOutput = 9, kBindCoverTarget = 10, kBindCoverDepth = 11, kBindDrawRank = 12, kBindMaskAlpha = 13,
                 kBindMaskDepth = 14;

// Per pixel (GL order): 1 + the farthest drawn target's object id (0: none) and its depth.
TargetCoverage coverTargets(FrameContext& frame, int maxLayers, bool allAreTargets, int maskSize) {
  FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  const auto& program = frame.shaders.compute("compose/dynamic_coverage.comp", buffer.layout().defines());
  gpu::Buffer target(buffer.pixels() * sizeof(std::uint32_t)), depth(buffer.pixels() * sizeof(float));
  target.bindBase(GL_SHADER_STORAGE_BUFFER, kBindCoverTarget);
  depth.bindBase(GL_SHADER_STORAGE_BUFFER, kBindCoverDepth);
  program.use();
  glUniform1i(program.uniform("uWidth"), buffer.width());
  glUniform1i(program.uniform("uHeight"), buffer.height());
  glUniform1i(program.uniform("uMaxLayers"), maxLayers);
  glUniform1i(program.uniform("uAllAreTargets"), allAreTargets ? 1 : 0);
  gpu::dispatchLinear(buffer.pixels());
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<std::uint32_t> targets(buffer.pixels());
  std::vector<float> depths(buffer.pixels());
  target.download(targets.data(), targets.size() * sizeof(std::uint32_t));
  depth.download(depths.data(), depths.size() * sizeof(float));
  return TargetCoverage::fromPixels(buffer.width(), buffer.height(), targets, depths, maskSize);
}
}  // namespace

// Binds what compose/dynamic_surfaces.glsl reads; the returned buffer must outlive the dispatch.
gpu::Buffer bindSurfaceInputs(FrameContext& frame, const std::vector<std::uint32_t>& drawRanks) {
  frame.fillAs<FragmentBuffer>().bindSorted();
  frame.gpuScene.bindObjectTable();
  gpu::Buffer ranks(drawRanks.size() * sizeof(std::uint32_t), drawRanks.data());
  ranks.bindBase(GL_SHADER_STORAGE_BUFFER, kBindDrawRank);
  return ranks;
}

AlphaMask buildDynamicMask(FrameContext& frame, const std::vector<std::uint32_t>& drawRanks, const DynamicSettings& settings) {
  const gpu::Buffer ranks = bindSurfaceInputs(frame, drawRanks);
  const AlphaMaskSettings mask =
      settings.mask.size > 0 ? settings.mask : AlphaMaskSettings::atImageResolution(settings.mask, frame.width, frame.height);
  return buildAlphaMask(coverTargets(frame, settings.maxLayers, settings.allAreTargets(frame.scene), mask.size), mask,
                        float(frame.width) / float(frame.height));
}

void composeDynamic(FrameContext& frame, const std::vector<std::uint32_t>& drawRanks, const AlphaMask& mask,
                    const DynamicSettings& settings) {
  FragmentBuffer& buffer = frame.fillAs<FragmentBuffer>();
  const gpu::Buffer ranks = bindSurfaceInputs(frame, drawRanks);
  const gpu::Buffer maskAlpha(mask.alpha.size() * sizeof(float), mask.alpha.data());
  const gpu::Buffer maskDepth(mask.depth.size() * sizeof(float), mask.depth.data());
  gpu::Buffer output(buffer.pixels() * sizeof(glm::vec4));
  output.bindBase(GL_SHADER_STORAGE_BUFFER, kBindOutput);
  maskAlpha.bindBase(GL_SHADER_STORAGE_BUFFER, kBindMaskAlpha);
  maskDepth.bindBase(GL_SHADER_STORAGE_BUFFER, kBindMaskDepth);

  const auto& program = frame.shaders.compute("compose/dynamic_compose.comp", buffer.layout().defines());
  program.use();
  glUniform1i(program.uniform("uWidth"), buffer.width());
  glUniform1i(program.uniform("uHeight"), buffer.height());
  glUniform4fv(program.uniform("uBackground"), 1, &frame.background[0]);
  glUniform1i(program.uniform("uMaskSize"), mask.size);
  glUniform1f(program.uniform("uAlphaTarget"), settings.mask.alphaTarget);
  glUniform1i(program.uniform("uSharedStacking"), settings.sharedStacking ? 1 : 0);
  glUniform1i(program.uniform("uMaxLayers"), settings.maxLayers);
  glUniform1i(program.uniform("uAllAreTargets"), settings.allAreTargets(frame.scene) ? 1 : 0);
  // The lens in GL pixels (row 0 = bottom); the settings count from the top left.
  const glm::vec4 lens(settings.lensCentre.x * float(buffer.width()), (1.0f - settings.lensCentre.y) * float(buffer.height()),
                       settings.lensRadius * float(buffer.height()), settings.active ? 1.0f : 0.0f);
  glUniform4fv(program.uniform("uLens"), 1, &lens[0]);
  dispatchCompose(frame, output, buffer.pixels(), "compose/dynamic_compose.comp", GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

}  // namespace tlab::render
