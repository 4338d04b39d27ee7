#pragma once
// Shared helpers of the `tlab serve` tests: start the server as a process (port 0 or a given one)
// and wait until it prints its participants' link; stop it; read what `tlab export --csv` stored
// per trial.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <regex>
#include <thread>

#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

namespace tlab::testing {

struct ServeProcess {
  pid_t pid = -1;
  int port = 0;
  std::string link;  // http://127.0.0.1:PORT/s/EXPERIMENT
};

// Starts `tlab serve` on `port` (0: any free one) and waits up to two minutes for its link.
inline ServeProcess startServe(const std::string& experiment, const std::filesystem::path& dir, int port, const std::string& tag) {
  const std::string out = (dir / ("serve_" + tag + ".out")).string(), err = (dir / ("serve_" + tag + ".err")).string();
  ServeProcess s;
  s.pid = spawnProcess({TLAB_EXE, "serve", experiment, "--db", (dir / "study.db").string(), "--listen", "127.0.0.1:" + std::to_string(port), "--quiet"},
                       out, err);
  static const std::regex printed("participants: (http://127\\.0\\.0\\.1:([0-9]+)/s/[^?]+)\\?");
  for (int i = 0; i < 1200; ++i) {
    std::smatch m;
    const std::string text = readText(out);
    if (std::regex_search(text, m, printed)) {
      s.link = m[1];
      s.port = std::stoi(m[2]);
      return s;
    }
    if (::waitpid(s.pid, nullptr, WNOHANG) == s.pid) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ADD_FAILURE() << "tlab serve did not start: " << readText(err);
  return s;
}

// Ctrl-C as a researcher would stop it; its exit code.
inline int stopServe(const ServeProcess& s) {
  ::kill(s.pid, SIGTERM);
  return waitProcess(s.pid);
}

struct StoredTrial {
  std::string status;  // the participant's
  std::string phase;
  int position = 0;    // among the participant's trials of its phase, from 1 (the page's "index")
  std::string rawAnswer;
  int rows = 0;        // one per stored response (a trial without a response: one row, responded 0)
  int responded = 0;
};

// (participant, sequence) → what trials.csv of `tlab export --csv` holds.
inline std::map<std::pair<std::string, int>, StoredTrial> exportedTrials(const std::filesystem::path& dir) {
  const auto csvDir = dir / "csv";
  const CommandResult r = runCommand(commandLine({TLAB_EXE, "export", (dir / "study.db").string(), "--csv", csvDir.string()}));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const auto rows = parseCsv(readText((csvDir / "trials.csv").string()));
  std::map<std::pair<std::string, int>, StoredTrial> out;
  if (rows.empty()) return out;
  std::map<std::string, std::size_t> column;
  for (std::size_t c = 0; c < rows[0].size(); ++c) column[rows[0][c]] = c;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& row = rows[i];
    StoredTrial& t = out[{row.at(column.at("participant")), std::stoi(row.at(column.at("sequence")))}];
    t.status = row.at(column.at("participant_status"));
    t.phase = row.at(column.at("phase"));
    t.rawAnswer = row.at(column.at("raw_answer"));
    t.responded += row.at(column.at("responded")) == "1";
    ++t.rows;
  }
  std::map<std::pair<std::string, std::string>, int> positions;  // trials come in sequence order
  for (auto& [key, t] : out) t.position = ++positions[{key.first, t.phase}];
  return out;
}

// The stored trial the page showed as `phase` trial `index` of `participant` (nullptr if none).
inline const StoredTrial* storedTrialAt(const std::map<std::pair<std::string, int>, StoredTrial>& trials, const std::string& participant,
                                        const std::string& phase, int index) {
  for (const auto& [key, t] : trials)
    if (key.first == participant && t.phase == phase && t.position == index) return &t;
  return nullptr;
}

}  // namespace tlab::testing
