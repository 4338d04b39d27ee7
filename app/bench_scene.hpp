#pragma once
// tlab bench render --scene (any scene, camera, styles, size) and tlab bench all (every style at
// 512² and 1024² on the standard scenes, then the seeds' own comparisons): steady-state per-frame
// and per-pass ms, fps, fragments and the GL that ran them — the table a lab runs on its own GPU.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace tlab::app {

struct SceneBenchOptions {
  std::string scene;
  std::string camera;
  std::vector<std::string> styles = {"constant"};
  std::vector<std::string> settings;  // --set key=value for every style
  std::string size = "512x512";
  int frames = 5;
  bool json = false;
  // --until PASS: every frame ends after that pass (RenderRequest::lastPass), so that a pass's own
  // work is the difference between two runs (bench/count_instructions.sh).
  std::string until;
  // --parts: also time each pass's parts (the connect pass's phases, the solve's steps, the fill's
  // rasterization and prefix sum, the compose's read-back), each between two glFinish calls.
  bool parts = false;
};

// One row per style; the last column is each style's frame time over the first style's.
void runSceneBench(const SceneBenchOptions& o);

void addBenchAll(CLI::App& bench);

}  // namespace tlab::app
