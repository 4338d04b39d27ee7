#pragma once
// Runs a shell command as a user would and captures its exit code, stdout and stderr.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace tlab::testing {

struct CommandResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline CommandResult runCommand(const std::string& command) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string errPath = (dir / ("tlab_test_err_" + std::to_string(::getpid()))).string();
  CommandResult r;
  FILE* pipe = ::popen((command + " 2>" + errPath).c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = readText(errPath);
  std::filesystem::remove(errPath);
  return r;
}

inline std::string quoted(const std::string& s) { return "'" + s + "'"; }

// The words of a command as one shell line, each quoted.
inline std::string commandLine(const std::vector<std::string>& words) {
  std::string line;
  for (const auto& w : words) line += (line.empty() ? "" : " ") + quoted(w);
  return line;
}

// A fresh, empty folder under the temp directory for one test.
inline std::filesystem::path freshDir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("tlab_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace tlab::testing
