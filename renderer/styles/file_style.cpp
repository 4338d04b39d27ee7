#include "renderer/styles/file_style.hpp"

#include <cmath>
#include <stdexcept>

#include "renderer/compose/style_file_compositor.hpp"
#include "renderer/ops/style_file_stage.hpp"

namespace tlab::render {

FragmentProperties FileStyle::properties(const StyleParams&, const SceneFacts& facts) const {
  FragmentProperties p = file_.declaration.properties;
  if (file_.declaration.neighbors) {  // what the connect pass reads (Carnecky Eqs. 1-3)
    p |= FragmentProperty::Normal;
    p |= FragmentProperty::DepthGradient;
    if (facts.componentCount > 1) p |= FragmentProperty::Ids;  // ε = ∞ across components
  }
  return p;
}

void FileStyle::validate(const StyleParams& params) const {
  for (const auto& p : file_.declaration.parameters)
    if (p.type == StyleValueType::Int && std::floor(params.number(p.spec.name)) != params.number(p.spec.name))
      throw std::invalid_argument("style '" + name() + "' parameter '" + p.spec.name + "' = " + params.choice(p.spec.name) +
                                  " is not a whole number");
  if (file_.declaration.neighbors && std::floor(params.number("iterations")) != params.number("iterations"))
    throw std::invalid_argument("style '" + name() + "' parameter 'iterations' = " + params.choice("iterations") + " is not a whole number");
}

std::vector<std::unique_ptr<RenderPass>> FileStyle::passes(const StyleParams& params) const {
  const auto program = std::make_shared<const StyleProgram>(file_.program(params));
  std::vector<std::unique_ptr<RenderPass>> p;
  if (!file_.declaration.neighbors) {
    p.push_back(functionPass("compose", [program](FrameContext& f) { composeStyleFile(f, *program, nullptr); }));
    return p;
  }
  // The per-fragment stage's values, shared by the two passes of one frame.
  auto values = std::make_shared<std::unique_ptr<gpu::Buffer>>();
  const int iterations = static_cast<int>(params.number("iterations"));
  p.push_back(functionPass("links+iterate", [program, values, iterations](FrameContext& f) {
    *values = runStyleFileStage(f, *program, iterations);
  }));
  p.push_back(functionPass("compose", [program, values](FrameContext& f) { composeStyleFile(f, *program, values->get()); }));
  return p;
}

void FileStyle::compile(gpu::ShaderCache& shaders) const {
  const StyleParams params = resolve({});
  const StyleProgram program = file_.program(params);
  const gpu::ShaderDefines layout = FragmentLayout(properties(params, SceneFacts{})).defines();
  if (!file_.declaration.neighbors) {
    program.compile(shaders, "compose/style_file_compose.comp", layout);
    return;
  }
  program.compile(shaders, "ops/style_file_stage.comp", styleStageDefines(layout));
  program.compile(shaders, "compose/style_file_compose.comp", styleStageDefines(layout));
}

}  // namespace tlab::render
