#pragma once
// ChildProcess: a program run as a child process with its stdout and stderr in a log file and no
// stdin, owned like a file handle — waited for (or polled) by its owner, and stopped (SIGTERM, then
// reaped) when the owner lets go of it while it still runs. posix_spawnp, so a multithreaded
// parent (tlab serve) never forks its threads' state.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace tlab::core {

class ChildProcess {
 public:
  // Starts argv[0] (found on PATH) with argv. Throws std::runtime_error with one line when it cannot.
  ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& log);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // The exit status once it has ended (128 + signal when killed), nullopt while it runs.
  std::optional<int> poll();
  // Waits for the end; the exit status as poll() gives it.
  int wait();

 private:
  pid_t pid_ = -1;
  std::optional<int> status_;
};

// Runs argv to its end with stdout and stderr in `log`; its exit status, 127 when it cannot start.
int runProgram(const std::vector<std::string>& argv, const std::filesystem::path& log);

}  // namespace tlab::core
