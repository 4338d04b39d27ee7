#include "renderer/frame/pass_timer.hpp"

#include "renderer/gpu/gl.hpp"

namespace tlab::render {

void PassTimer::finish() { glFinish(); }

}  // namespace tlab::render
