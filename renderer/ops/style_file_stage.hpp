#pragma once
// The per-fragment stage of a style file (ops/style_file_stage.comp): the Carnecky Alg. 2 links
// (ops/connect_pass), then N iterations of the user's iterate() over a per-fragment value,
// ping-pong, before the style's compositor reads it.
#include <memory>
#include <vector>

#include "renderer/frame/frame_context.hpp"
#include "renderer/params/style_program.hpp"

namespace tlab::render {

// The uniforms of the illustration buffer and the frame that both stages of a style file read.
void setStyleFrameUniforms(const gpu::ShaderProgram& program, const FrameContext& frame);

// The value of every fragment of the frame's buffer after `iterations` iterations.
std::unique_ptr<gpu::Buffer> runStyleFileStage(FrameContext& frame, const StyleProgram& style, int iterations);

// The stage's defines for the frame's buffer (exposed for the design-time compile).
gpu::ShaderDefines styleStageDefines(const gpu::ShaderDefines& layoutDefines);

}  // namespace tlab::render
