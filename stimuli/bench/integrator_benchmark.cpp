#include "stimuli/bench/integrator_benchmark.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include <cairo-svg.h>

#include "core/image.hpp"
#include "core/seeded_random.hpp"
#include "stimuli/fields/abc_flow.hpp"
#include "stimuli/fields/double_gyre.hpp"
#include "stimuli/fields/linear_saddle.hpp"
#include "stimuli/fields/solid_rotation.hpp"
#include "stimuli/fields/stiff_relaxation_field.hpp"
#include "stimuli/integration/particle_integrator.hpp"

namespace tlab::stimuli {

namespace {

using ExactSolution = std::function<glm::dvec3(const glm::dvec3&, double, double)>;

struct BenchmarkCase {
  std::unique_ptr<VectorField> field;
  ExactSolution exact;     // empty: use a tight-tolerance reference
  double duration;
  glm::dvec3 center, spread;  // particles start in center ± spread
  std::vector<double> rk4Steps;
};

std::vector<BenchmarkCase> benchmarkCases(bool quick) {
  std::vector<BenchmarkCase> cases;
  auto rotation = std::make_unique<SolidRotation>(1.0);
  const SolidRotation* r = rotation.get();
  cases.push_back({std::move(rotation), [r](auto x, auto t0, auto t1) { return r->exactPosition(x, t0, t1); }, 2.0 * std::numbers::pi,
                   {0.0, 0.0, 0.0}, {1.0, 1.0, 0.5}, {0.1, 0.03, 0.01, 0.003}});
  auto saddle = std::make_unique<LinearSaddle>(1.0, -0.5);
  const LinearSaddle* s = saddle.get();
  cases.push_back({std::move(saddle), [s](auto x, auto t0, auto t1) { return s->exactPosition(x, t0, t1); }, 3.0, {0.0, 0.0, 0.0},
                   {1.0, 1.0, 1.0}, {0.1, 0.03, 0.01, 0.003}});
  auto stiff = std::make_unique<StiffRelaxationField>();
  const StiffRelaxationField* k = stiff.get();
  cases.push_back({std::move(stiff), [k](auto x, auto t0, auto t1) { return k->exactPosition(x, t0, t1); }, 2.0 * std::numbers::pi,
                   {0.0, 0.0, 0.0}, {1.0, 1.0, 0.5}, {3e-4, 2.5e-4, 1e-4, 3e-5}});
  cases.push_back({std::make_unique<AbcFlow>(), {}, 5.0, {0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, {0.1, 0.03, 0.01, 0.003}});
  cases.push_back({std::make_unique<DoubleGyre>(), {}, 10.0, {1.0, 0.5, 0.0}, {0.9, 0.45, 0.0}, {0.3, 0.1, 0.03, 0.01}});
  if (quick)
    for (auto& c : cases) c.rk4Steps.resize(2);
  return cases;
}

std::vector<glm::dvec3> startPoints(const BenchmarkCase& c, int n) {
  core::SeededRandom random(17);
  std::vector<glm::dvec3> points;
  for (int i = 0; i < n; ++i) {
    points.push_back(c.center + c.spread * glm::dvec3(random.pointZFirst(-1.0f, 1.0f)));
  }
  return points;
}

std::string formatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

IntegratorBenchmarkRow measure(const BenchmarkCase& c, const std::vector<glm::dvec3>& starts, const std::vector<glm::dvec3>& truth,
                               const IntegratorSettings& settings, int repeats) {
  const ParticleIntegrator integrator(*c.field, settings);
  IntegratorBenchmarkRow row;
  row.field = c.field->name();
  row.integrator = integratorName(settings.kind);
  const bool fixed = settings.kind == IntegratorKind::RungeKutta4;
  row.settingValue = fixed ? settings.step : settings.absoluteTolerance;
  row.setting = (fixed ? "h=" : "tol=") + formatNumber(row.settingValue);
  row.reference = c.exact ? "exact" : "dopri5 tol=1e-12";
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    double error = 0.0, steps = 0.0;
    const auto begin = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < starts.size(); ++i) {
      const ParticleAdvance a = integrator.advance(starts[i], 0.0, c.duration);
      const double e = glm::distance(a.position, truth[i]);
      error = std::isfinite(e) ? std::max(error, e) : std::numeric_limits<double>::infinity();
      steps += double(a.steps);
    }
    times.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - begin).count() / double(starts.size()));
    row.error = error;
    row.steps = steps / double(starts.size());
  }
  row.microseconds = median(times);
  return row;
}

}  // namespace

std::vector<IntegratorBenchmarkRow> runIntegratorBenchmark(const IntegratorBenchmarkOptions& o) {
  std::vector<IntegratorBenchmarkRow> rows;
  const std::vector<double> tolerances = o.quick ? std::vector<double>{1e-4, 1e-7} : std::vector<double>{1e-3, 1e-5, 1e-7, 1e-9};
  for (const auto& c : benchmarkCases(o.quick)) {
    const auto starts = startPoints(c, o.particles);
    std::vector<glm::dvec3> truth;
    IntegratorSettings reference;
    reference.absoluteTolerance = reference.relativeTolerance = 1e-12;
    reference.step = 1e-4;
    for (const auto& x : starts)
      truth.push_back(c.exact ? c.exact(x, 0.0, c.duration) : ParticleIntegrator(*c.field, reference).advance(x, 0.0, c.duration).position);
    for (const double h : c.rk4Steps) {
      IntegratorSettings s;
      s.kind = IntegratorKind::RungeKutta4;
      s.step = h;
      rows.push_back(measure(c, starts, truth, s, o.repeats));
    }
    for (const auto kind : {IntegratorKind::DormandPrince, IntegratorKind::Rosenbrock4})
      for (const double tol : tolerances) {
        IntegratorSettings s;
        s.kind = kind;
        s.step = 1e-3;
        s.absoluteTolerance = s.relativeTolerance = tol;
        rows.push_back(measure(c, starts, truth, s, o.repeats));
      }
  }
  return rows;
}

std::string integratorBenchmarkCsv(const std::vector<IntegratorBenchmarkRow>& rows) {
  std::ostringstream out;
  out << "field,integrator,setting,reference,error,microseconds,steps\n";
  for (const auto& r : rows)
    out << r.field << ',' << r.integrator << ',' << r.setting << ',' << r.reference << ',' << formatNumber(r.error) << ','
        << formatNumber(r.microseconds) << ',' << formatNumber(r.steps) << '\n';
  return out.str();
}

std::string integratorBenchmarkTable(const std::vector<IntegratorBenchmarkRow>& rows) {
  std::ostringstream out;
  char line[256];
  std::snprintf(line, sizeof line, "%-17s %-12s %-11s %-17s %11s %12s %11s\n", "field", "integrator", "setting", "reference", "max error",
                "us/particle", "steps");
  out << line;
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "%-17s %-12s %-11s %-17s %11.3e %12.1f %11.0f\n", r.field.c_str(), r.integrator.c_str(),
                  r.setting.c_str(), r.reference.c_str(), r.error, r.microseconds, r.steps);
    out << line;
  }
  return out.str();
}

namespace {

struct Panel {
  double x, y, w, h;
};

void drawText(cairo_t* cr, double x, double y, const std::string& text, double size) {
  cairo_set_font_size(cr, size);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

// One log–log panel: x = log10(µs), y = log10(error), clamped to the panel's decades.
void drawPanel(cairo_t* cr, const Panel& p, const std::string& field, const std::vector<IntegratorBenchmarkRow>& rows) {
  std::vector<const IntegratorBenchmarkRow*> mine;
  for (const auto& r : rows)
    if (r.field == field) mine.push_back(&r);
  double x0 = 1e9, x1 = -1e9;
  for (const auto* r : mine) x0 = std::min(x0, std::log10(r->microseconds)), x1 = std::max(x1, std::log10(r->microseconds));
  x0 = std::floor(x0), x1 = std::max(x0 + 1.0, std::ceil(x1));
  const double y0 = -14.0, y1 = 2.0;
  const auto px = [&](double lx) { return p.x + (lx - x0) / (x1 - x0) * p.w; };
  const auto py = [&](double ly) { return p.y + p.h - (std::clamp(ly, y0, y1) - y0) / (y1 - y0) * p.h; };
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, p.x, p.y, p.w, p.h);
  cairo_stroke(cr);
  drawText(cr, p.x, p.y - 6, field, 13);
  for (int d = int(x0); d <= int(x1); ++d) drawText(cr, px(d) - 8, p.y + p.h + 14, "1e" + std::to_string(d), 9);
  for (int d = int(y0); d <= int(y1); d += 2) drawText(cr, p.x - 34, py(d) + 3, "1e" + std::to_string(d), 9);
  drawText(cr, p.x + p.w / 2 - 40, p.y + p.h + 28, "microseconds / particle", 10);
  const std::map<std::string, std::array<double, 3>> colors = {
      {"rk4", {0.85, 0.2, 0.15}}, {"dopri5", {0.15, 0.45, 0.85}}, {"rosenbrock4", {0.2, 0.65, 0.25}}};
  double legendY = p.y + 14;
  for (const auto& [name, rgb] : colors) {
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    bool first = true;
    for (const auto* r : mine) {
      if (r->integrator != name) continue;
      const double ly = std::isfinite(r->error) ? std::log10(std::max(r->error, 1e-16)) : y1;
      const double x = px(std::log10(r->microseconds)), y = py(ly);
      if (first) cairo_move_to(cr, x, y);
      else cairo_line_to(cr, x, y);
      first = false;
    }
    cairo_stroke(cr);
    for (const auto* r : mine) {
      if (r->integrator != name) continue;
      const double ly = std::isfinite(r->error) ? std::log10(std::max(r->error, 1e-16)) : y1;
      cairo_arc(cr, px(std::log10(r->microseconds)), py(ly), 2.5, 0, 2 * std::numbers::pi);
      cairo_fill(cr);
    }
    drawText(cr, p.x + p.w - 80, legendY, name, 10);
    legendY += 13;
  }
}

}  // namespace

void writeIntegratorBenchmarkSvg(const std::vector<IntegratorBenchmarkRow>& rows, const std::string& path) {
  std::vector<std::string> fields;
  for (const auto& r : rows)
    if (std::find(fields.begin(), fields.end(), r.field) == fields.end()) fields.push_back(r.field);
  const double panelW = 300, panelH = 220, margin = 60;
  const double width = margin + double(fields.size()) * (panelW + margin), height = panelH + 2 * margin + 20;
  std::vector<std::uint8_t> bytes;
  const auto append = [](void* closure, const unsigned char* data, unsigned int length) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(closure);
    out->insert(out->end(), data, data + length);
    return CAIRO_STATUS_SUCCESS;
  };
  cairo_surface_t* surface = cairo_svg_surface_create_for_stream(append, &bytes, width, height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  drawText(cr, margin, 22, "tlab bench integrate: max end-point error vs. run time", 14);
  for (std::size_t i = 0; i < fields.size(); ++i)
    drawPanel(cr, {margin + double(i) * (panelW + margin), margin, panelW, panelH}, fields[i], rows);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const cairo_status_t status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) throw std::runtime_error(path + ": cannot draw the SVG plot (" + cairo_status_to_string(status) + ")");
  core::writeFileAtomically(path, bytes);
}

}  // namespace tlab::stimuli
