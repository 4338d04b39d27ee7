#pragma once
// `tlab bench integrate`: the error of each integrator and tolerance (or RK4 step) against the
// exact solution (solid rotation, linear saddle, the stiff relaxation field) or against a
// tight-tolerance Dormand–Prince reference (ABC flow, double gyre), versus run time.
#include <cstddef>
#include <string>
#include <vector>

namespace tlab::stimuli {

struct IntegratorBenchmarkRow {
  std::string field;
  std::string integrator;      // rk4, dopri5, rosenbrock4
  std::string setting;         // "h=0.01" or "tol=1e-06"
  double settingValue = 0.0;   // the step or the tolerance
  std::string reference;       // "exact" or "dopri5 tol=1e-12"
  double error = 0.0;          // largest end-point error over the particles (inf: blew up)
  double microseconds = 0.0;   // per particle trajectory (median of repeats)
  double steps = 0.0;          // per particle trajectory
};

struct IntegratorBenchmarkOptions {
  int particles = 8;
  int repeats = 3;
  bool quick = false;          // fewer settings (for tests)
};

std::vector<IntegratorBenchmarkRow> runIntegratorBenchmark(const IntegratorBenchmarkOptions& options);

std::string integratorBenchmarkCsv(const std::vector<IntegratorBenchmarkRow>& rows);
std::string integratorBenchmarkTable(const std::vector<IntegratorBenchmarkRow>& rows);
// Log–log error vs. time, one panel per field, one line per integrator (Cairo SVG surface).
void writeIntegratorBenchmarkSvg(const std::vector<IntegratorBenchmarkRow>& rows, const std::string& path);

}  // namespace tlab::stimuli
