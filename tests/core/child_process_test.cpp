// ChildProcess: a program's exit status by wait and by poll, its output in the log, a program that
// cannot start named in one line, and a child still running when its owner lets go stopped and reaped.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "core/child_process.hpp"

namespace tlab::core {
namespace {

namespace fs = std::filesystem;

fs::path logFile(const std::string& name) { return fs::temp_directory_path() / ("tlab_child_" + name + "_" + std::to_string(::getpid()) + ".log"); }

std::string text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ChildProcess, ExitStatusAndBothStreamsInTheLog) {
  const fs::path log = logFile("status");
  ChildProcess p({"sh", "-c", "echo out; echo err >&2; exit 3"}, log);
  EXPECT_EQ(p.wait(), 3);
  EXPECT_EQ(p.poll(), 3) << "the status stays once known";
  EXPECT_EQ(text(log), "out\nerr\n");
  EXPECT_EQ(runProgram({"sh", "-c", "exit 0"}, log), 0);
  fs::remove(log);
}

TEST(ChildProcess, PollIsEmptyWhileItRunsAndAMissingProgramIsNamed) {
  const fs::path log = logFile("poll");
  {
    ChildProcess p({"sh", "-c", "read line"}, log);  // stdin is /dev/null: read ends at once with status 1
    EXPECT_EQ(p.wait(), 1);
  }
  ChildProcess sleeper({"sleep", "30"}, log);
  EXPECT_FALSE(sleeper.poll().has_value());
  try {
    ChildProcess missing({"tlab-no-such-program"}, log);
    FAIL() << "started a program that does not exist";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("tlab-no-such-program: cannot start (", 0), 0u) << e.what();
  }
  EXPECT_EQ(runProgram({"tlab-no-such-program"}, log), 127);
  fs::remove(log);
}

TEST(ChildProcess, LetGoWhileRunningItIsStoppedAndReaped) {
  const fs::path log = logFile("stop");
  pid_t pid = -1;
  {
    ChildProcess p({"sh", "-c", "echo $$; exec sleep 30"}, log);
    while (text(log).empty()) ::usleep(1000);  // until the child has said who it is
    pid = std::stoi(text(log));
    EXPECT_EQ(::kill(pid, 0), 0) << "running";
  }
  EXPECT_EQ(::kill(pid, 0), -1) << "stopped and reaped: no such process any more";
  fs::remove(log);
}

}  // namespace
}  // namespace tlab::core
