#pragma once
// A participant's `tlab run` in a real GLFW window on its own Xvfb display, driven with xdotool
// (tests/study/window_run_test.cpp, tests/study/replay_window_test.cpp): the session, its window,
// and the stored plan once the runner has written it.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/store/sqlite_database.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

namespace tlab::testing {

inline const std::string kTlab = TLAB_EXE;
inline bool haveTool(const std::string& name) { return runCommand("command -v " + name).exitCode == 0; }

inline void pause(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

struct StoredTrial {
  nlohmann::json question;
};

// The trials of the participant once the runner has stored its plan (polls up to ~20 s).
inline std::vector<StoredTrial> waitForTrials(const std::string& db) {
  for (int i = 0; i < 200; ++i) {
    try {
      study::Database d(db, false);
      auto s = d.prepare("SELECT question_json FROM trials ORDER BY sequence");
      std::vector<StoredTrial> out;
      while (s.step()) out.push_back({nlohmann::json::parse(s.text(0))});
      if (!out.empty()) return out;
    } catch (const std::exception&) {
    }
    pause(100);
  }
  return {};
}

// The screen layout the window logged at the onset of its `index`-th trial (0-based, in the
// order of the session): where it drew the stimulus, each label, the plan and the gauge. Waits
// until the onset is committed (it is, before the trial takes any answer); null if it never is.
inline nlohmann::json waitForOnsetLayout(const std::string& db, int index) {
  for (int i = 0; i < 200; ++i) {
    try {
      study::Database d(db, false);
      auto s = d.prepare("SELECT e.detail FROM events e JOIN trials t ON t.id = e.trial WHERE e.kind = 'onset' "
                         "ORDER BY t.sequence LIMIT 1 OFFSET " + std::to_string(index));
      if (s.step()) return nlohmann::json::parse(s.text(0));
    } catch (const std::exception&) {
    }
    pause(100);
  }
  return nullptr;
}

// `tlab run EXPERIMENT` for one participant on its own Xvfb display (apart from window_cli_test's
// 90..189), with xdotool driving its window.
struct WindowSession {
  std::filesystem::path dir;
  std::string db, env, window;
  pid_t xvfb = -1, tlab = -1;

  WindowSession(const std::string& name, int displayBase, const std::string& experiment, const std::string& participant)
      : dir(freshDir(name)), db((dir / "study.db").string()) {
    const std::string display = ":" + std::to_string(displayBase + ::getpid() % 100);
    xvfb = spawnProcess({"Xvfb", display, "-screen", "0", "800x600x24"}, (dir / "xvfb.out").string(), (dir / "xvfb.err").string());
    pause(800);
    env = "DISPLAY=" + display;
    tlab = spawnProcess({kTlab, "run", studyData(experiment), "--participant", participant, "--db", db, "--size", "640x480"},
                        (dir / "run.out").string(), (dir / "run.err").string(), {env});
    const auto r = runCommand(env + " timeout 20 xdotool search --sync --name 'tlab run' | head -1");
    window = r.out.substr(0, r.out.find('\n'));
  }
  CommandResult xdo(const std::string& args) const { return runCommand(env + " xdotool " + args); }
  // Waits for tlab to end, stops Xvfb; tlab's exit code.
  int finish() {
    const int code = waitProcess(tlab);
    ::kill(xvfb, SIGTERM);
    waitProcess(xvfb);
    return code;
  }
  std::string out() const { return readText((dir / "run.out").string()); }
  std::string err() const { return readText((dir / "run.err").string()); }
};

// Presses `key` in the session's window, then waits `ms`.
inline void press(const WindowSession& session, const std::string& key, int ms) {
  session.xdo("key --window " + session.window + " " + key);
  pause(ms);
}

}  // namespace tlab::testing
