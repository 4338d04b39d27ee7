#pragma once
// Shared helpers of the study tests: paths of the test experiments and the examples, a query's
// number from a study database, and a minimal RFC 4180 CSV reader to check what `tlab export`
// wrote byte for byte.
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "study/store/sqlite_database.hpp"

namespace tlab::testing {

inline std::string studyData(const std::string& name) { return std::string(TLAB_SOURCE_DIR) + "/tests/study/data/" + name; }
inline std::string example(const std::string& name) { return std::string(TLAB_SOURCE_DIR) + "/examples/" + name; }

// The integer in `column` of the first row a query on the database file `db` returns (-1: no row).
inline std::int64_t queryCount(const std::string& db, const std::string& sql, int column = 0) {
  study::Database d(db, false);
  auto s = d.prepare(sql);
  return s.step() ? s.integer(column) : -1;
}

// Rows of fields; quoted fields may hold commas, quotes ("") and line breaks; rows end in CRLF or LF.
inline std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row;
  std::string field;
  bool quoted = false, any = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') field += '"', ++i;
      else if (c == '"') quoted = false;
      else field += c;
      continue;
    }
    if (c == '"') quoted = true, any = true;
    else if (c == ',') row.push_back(field), field.clear();
    else if (c == '\r') continue;
    else if (c == '\n') {
      row.push_back(field);
      rows.push_back(row);
      row.clear();
      field.clear();
      any = false;
    } else field += c, any = true;
  }
  if (any || !row.empty()) {
    row.push_back(field);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace tlab::testing

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace tlab::testing {

// Starts `argv` with stdout (and stderr) redirected to files; returns its pid.
inline pid_t spawnProcess(const std::vector<std::string>& argv, const std::string& outPath, const std::string& errPath,
                          const std::vector<std::string>& env = {}) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int out = ::open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, 1);
    ::dup2(err, 2);
    for (const auto& e : env) ::putenv(const_cast<char*>(e.c_str()));
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    ::execvp(args[0], args.data());
    ::_exit(127);
  }
  return pid;
}

// Waits for the process; its exit code, or -signal when it was killed.
inline int waitProcess(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

// One acknowledged response of `tlab simulate --trials`, printed only after its transaction committed.
struct Ack {
  std::string participant;
  int sequence = 0;
  std::string answer;
};

// "ack sim-001 3/12 test block 1 layer trial 1 q2 answer=2 correct rt=..." (complete lines only).
inline std::vector<Ack> parseAcks(const std::string& text) {
  std::vector<Ack> acks;
  std::size_t start = 0;
  for (std::size_t end = text.find('\n'); end != std::string::npos; start = end + 1, end = text.find('\n', start)) {
    std::istringstream line(text.substr(start, end - start));
    std::string word, progress;
    Ack a;
    if (!(line >> word) || word != "ack") continue;
    line >> a.participant >> progress;
    a.sequence = std::stoi(progress.substr(0, progress.find('/')));
    while (line >> word)
      if (word.rfind("answer=", 0) == 0) a.answer = word.substr(7);
    acks.push_back(a);
  }
  return acks;
}

}  // namespace tlab::testing
