#pragma once
#include <stdexcept>
#include <string>
#include <string_view>

namespace tlab::gpu {

// A GL failure: a GL error code, a shader compile/link log, an exhausted resource.
class GlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws GlError naming `what` when glGetError reports an error.
void checkGl(std::string_view what);

}  // namespace tlab::gpu
