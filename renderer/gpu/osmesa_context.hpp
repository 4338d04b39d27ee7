#pragma once
// A headless OpenGL 4.5 core context through OSMesa (Mesa llvmpipe), loaded at run time.
#include <vector>

#include "renderer/gpu/gpu_context.hpp"

namespace tlab::gpu {

// Throws GlError when libOSMesa cannot be loaded or gives no 4.5 core context.
std::unique_ptr<GpuContext> createOsmesaContext();

}  // namespace tlab::gpu
