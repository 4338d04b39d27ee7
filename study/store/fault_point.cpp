#include "study/store/fault_point.hpp"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace tlab::study {

void faultPoint(std::string_view name, int count) {
  const char* wanted = std::getenv("TLAB_STOP_AT");
  if (!wanted) return;
  const std::string here = count > 0 ? std::string(name) + ":" + std::to_string(count) : std::string(name);
  if (here != wanted) return;
  std::fprintf(stderr, "tlab: stopped at fault point %s (TLAB_STOP_AT)\n", here.c_str());
  std::fflush(stderr);
  std::fflush(stdout);
  std::raise(SIGSTOP);
}

}  // namespace tlab::study
