#pragma once
// Every `tlab` subcommand is one small file in app/ that registers itself on the CLI11 app.
// Commands only parse arguments and call the libraries.
#include <CLI/CLI.hpp>

namespace tlab::app {

void addRenderCommand(CLI::App& app);    // cmd_render.cpp
void addInspectCommand(CLI::App& app);   // cmd_inspect.cpp
void addBenchCommand(CLI::App& app);     // cmd_bench.cpp
void addDiffusionBench(CLI::App& bench); // cmd_bench_diffusion.cpp (tlab bench diffusion)
void addPeelBench(CLI::App& bench);      // cmd_bench_peel.cpp (tlab bench peel)
void addDynamicBench(CLI::App& bench);   // cmd_bench_dynamic.cpp (tlab bench dynamic)
void addBucketBench(CLI::App& bench);    // cmd_bench_buckets.cpp (tlab bench buckets)
void addGalleryCommand(CLI::App& app);   // cmd_gallery.cpp
void addFiguresCommand(CLI::App& app);   // cmd_figures.cpp
void addStatsCommand(CLI::App& app);     // cmd_stats.cpp
void addReproduceCommand(CLI::App& app); // cmd_reproduce.cpp
void addStatcheckCommand(CLI::App& app); // cmd_statcheck.cpp
void addReportCommand(CLI::App& app);    // cmd_report.cpp
void addStimuliCommand(CLI::App& app);   // cmd_stimuli.cpp
void addIntegrateBench(CLI::App& bench); // cmd_stimuli.cpp: tlab bench integrate
void addTaskCommand(CLI::App& app);      // cmd_task.cpp
void addDesignCommand(CLI::App& app);    // cmd_design.cpp
void addTextsCommand(CLI::App& app);     // cmd_texts.cpp
void addRunCommand(CLI::App& app);       // cmd_run.cpp
void addServeCommand(CLI::App& app);     // cmd_serve.cpp
void addLoadtestCommand(CLI::App& app);  // cmd_loadtest.cpp
void addSimulateCommand(CLI::App& app);  // cmd_simulate.cpp
void addExportCommand(CLI::App& app);    // cmd_export.cpp
void addReplayCommand(CLI::App& app);    // cmd_replay.cpp
void addAnalyzeCommand(CLI::App& app);   // cmd_analyze.cpp
void addDropCommand(CLI::App& app);      // cmd_drop.cpp
void addTimingCommand(CLI::App& app);    // cmd_timing.cpp
void addVersionCommand(CLI::App& app);   // cmd_version.cpp
void addDemoCommand(CLI::App& app);      // cmd_demo.cpp
void addSceneCommand(CLI::App& app);     // cmd_scene.cpp

}  // namespace tlab::app
