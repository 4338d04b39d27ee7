#pragma once
// A raster pass that captures fragments into storage buffers (the illustration buffer's fills,
// the k-buffer's passes): binds the attachment-less framebuffer at width × height with depth
// test, culling and blending off, uses `program` and sets uView, uProjection and uWidth (a program
// that shades compiled the lighting model in: withLighting).
// The caller sets its own uniforms, then endFragmentCapture draws the scene (offsetting the
// program's gl_PrimitiveID by uPrimitiveBase where it has one: GpuScene::draw) and waits for the
// storage writes.
#include "renderer/frame/gpu_scene.hpp"
#include "renderer/frame/raster_uniforms.hpp"
#include "renderer/gpu/gl_objects.hpp"
#include "renderer/gpu/shader_program.hpp"

namespace tlab::render {

void beginFragmentCapture(const gpu::Framebuffer& framebuffer, int width, int height, const gpu::ShaderProgram& program,
                          const RasterUniforms& u);
void endFragmentCapture(const GpuScene& scene, const gpu::ShaderProgram& program);

}  // namespace tlab::render
