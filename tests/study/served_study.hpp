#pragma once
// A `tlab serve` process for end-to-end tests: started on a free loopback port (--listen
// 127.0.0.1:0, or a given port to restart on), its stdout read until the participants' link gives
// the port, stopped with SIGTERM (or killed with SIGKILL to test crashes) when the test ends.
#include <chrono>
#include <filesystem>
#include <regex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

namespace tlab::testing {

class ServedStudy {
 public:
  // `extra`: more arguments of tlab serve.
  ServedStudy(const std::string& experiment, const std::string& db, const std::filesystem::path& dir, int port = 0,
              const std::vector<std::string>& extra = {})
      : out_((dir / ("serve-" + std::to_string(port) + "-" + std::to_string(++starts()) + ".out")).string()), err_(out_ + ".err") {
    std::vector<std::string> command{TLAB_EXE, "serve", experiment, "--db", db, "--listen", "127.0.0.1:" + std::to_string(port), "--quiet"};
    command.insert(command.end(), extra.begin(), extra.end());
    pid_ = spawnProcess(command, out_, err_);
    waitForPort();
  }
  ~ServedStudy() { stop(SIGTERM); }
  ServedStudy(const ServedStudy&) = delete;
  ServedStudy& operator=(const ServedStudy&) = delete;

  int port() const { return port_; }
  // The participants' link without its query: http://127.0.0.1:PORT/s/EXPERIMENT.
  const std::string& link() const { return link_; }
  std::string stdoutText() const { return readText(out_); }
  std::string stderrText() const { return readText(err_); }
  std::string adminToken() const {
    std::smatch m;
    const std::string out = stdoutText();
    if (!std::regex_search(out, m, std::regex("admin\\?token=([0-9a-f]{64})"))) throw std::runtime_error("no admin token in: " + out);
    return m[1];
  }
  // SIGTERM: a clean stop; SIGKILL: a crash. Returns the exit code (-signal when killed).
  int stop(int signal) {
    if (pid_ <= 0) return status_;
    ::kill(pid_, signal);
    status_ = waitProcess(pid_);
    pid_ = -1;
    return status_;
  }

 private:
  static int& starts() {
    static int n = 0;
    return n;
  }
  void waitForPort() {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    const std::regex printed("participants: (http://127\\.0\\.0\\.1:([0-9]+)/s/[^?]+)\\?");
    while (std::chrono::steady_clock::now() < deadline) {
      std::smatch m;
      const std::string out = stdoutText();
      if (std::regex_search(out, m, printed)) {
        link_ = m[1];
        port_ = std::stoi(m[2]);
        return;
      }
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        throw std::runtime_error("tlab serve exited before listening: " + stderrText());
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    throw std::runtime_error("tlab serve did not print its link within 120 s: " + stderrText());
  }

  std::string out_, err_, link_;
  pid_t pid_ = -1;
  int port_ = 0;
  int status_ = -1;
};

}  // namespace tlab::testing
