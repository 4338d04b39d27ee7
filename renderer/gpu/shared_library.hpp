#pragma once
// A shared library opened at run time (dlopen), so one tlab binary runs where only a GPU driver's
// libEGL, or only Mesa's libOSMesa, is installed. The handle is kept open for the life of the
// process (RTLD_NODELETE): GL drivers do not survive being unloaded while the process runs.
#include <string>
#include <vector>

namespace tlab::gpu {

class SharedLibrary {
 public:
  // Opens the first of `names` that loads; throws GlError naming every name tried, the loader's
  // reason and `remedy` when none does.
  SharedLibrary(const std::vector<std::string>& names, const std::string& remedy);
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  const std::string& name() const { return name_; }
  // The symbol's address; throws GlError when the library lacks it.
  void* symbol(const char* symbolName) const;
  template <typename F>
  F function(const char* symbolName) const {
    return reinterpret_cast<F>(symbol(symbolName));
  }

 private:
  void* handle_ = nullptr;
  std::string name_;
};

}  // namespace tlab::gpu
