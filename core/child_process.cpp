#include "core/child_process.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace tlab::core {

namespace {

int exitStatus(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }

// posix_spawn's file actions, released on every path.
struct FileActions {
  posix_spawn_file_actions_t actions;
  FileActions() { posix_spawn_file_actions_init(&actions); }
  ~FileActions() { posix_spawn_file_actions_destroy(&actions); }
};

}  // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& log) {
  if (argv.empty()) throw std::invalid_argument("ChildProcess: no program");
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  FileActions f;
  posix_spawn_file_actions_addopen(&f.actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&f.actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&f.actions, 1, 2);
  if (const int error = posix_spawnp(&pid_, args[0], &f.actions, nullptr, args.data(), environ); error != 0)
    throw std::runtime_error(argv[0] + ": cannot start (" + std::strerror(error) + ")");
}

ChildProcess::~ChildProcess() {
  if (status_ || pid_ <= 0) return;
  ::kill(pid_, SIGTERM);
  wait();
}

std::optional<int> ChildProcess::poll() {
  if (status_) return status_;
  int status = 0;
  const pid_t done = ::waitpid(pid_, &status, WNOHANG);
  if (done == pid_) status_ = exitStatus(status);
  else if (done < 0 && errno != EINTR) status_ = 127;  // not our child any more: nothing to wait for
  return status_;
}

int ChildProcess::wait() {
  while (!status_) {
    int status = 0;
    if (::waitpid(pid_, &status, 0) == pid_) status_ = exitStatus(status);
    else if (errno != EINTR) status_ = 127;
  }
  return *status_;
}

int runProgram(const std::vector<std::string>& argv, const std::filesystem::path& log) {
  try {
    return ChildProcess(argv, log).wait();
  } catch (const std::runtime_error&) {
    return 127;
  }
}

}  // namespace tlab::core
