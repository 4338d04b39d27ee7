#include "renderer/gpu/shared_library.hpp"

#include <dlfcn.h>

#include "renderer/gpu/gl_error.hpp"

namespace tlab::gpu {

SharedLibrary::SharedLibrary(const std::vector<std::string>& names, const std::string& remedy) {
  std::string reasons;
  for (const auto& n : names) {
    handle_ = dlopen(n.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (handle_) {
      name_ = n;
      return;
    }
    const char* why = dlerror();
    reasons += (reasons.empty() ? "" : "; ") + std::string(why ? why : n + ": cannot be opened");
  }
  throw GlError("cannot load " + names.front() + " (" + reasons + ") - " + remedy);
}

void* SharedLibrary::symbol(const char* symbolName) const {
  dlerror();
  void* p = dlsym(handle_, symbolName);
  if (!p) throw GlError(name_ + " has no " + symbolName + " (too old a driver?)");
  return p;
}

}  // namespace tlab::gpu
