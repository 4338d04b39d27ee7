#pragma once
// tlab bench floor (app/cmd_bench_floor.cpp): each pass's bytes per frame against this machine's
// streaming bandwidth.
#include <CLI/CLI.hpp>

namespace tlab::app {

void addFloorBench(CLI::App& bench);

}  // namespace tlab::app
