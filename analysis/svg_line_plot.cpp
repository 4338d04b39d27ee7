// Lines through (x, y) points on linear or log10 axes (svg_plots.hpp), on the shared axes
// (svg_axes.hpp). Values are drawn in axis space: log10 of the value on a log axis, non-positive
// values skipped there.
#include <algorithm>
#include <cmath>

#include "analysis/analysis_error.hpp"
#include "analysis/svg_axes.hpp"
#include "analysis/svg_plots.hpp"

namespace tlab::analysis {

namespace {

using namespace svg;

double axis(double v, bool log) { return log ? std::log10(v) : v; }
bool usable(double v, bool log) { return std::isfinite(v) && (!log || v > 0); }

// The range of the drawable points in axis space.
struct Range {
  double xMin = INFINITY, xMax = -INFINITY, yMin = INFINITY, yMax = -INFINITY;
};

Range dataRange(const LinePlot& plot) {
  Range r;
  for (const auto& s : plot.series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (usable(s.x[i], plot.logX) && usable(s.y[i], plot.logY)) {
        r.xMin = std::min(r.xMin, axis(s.x[i], plot.logX));
        r.xMax = std::max(r.xMax, axis(s.x[i], plot.logX));
        r.yMin = std::min(r.yMin, axis(s.y[i], plot.logY));
        r.yMax = std::max(r.yMax, axis(s.y[i], plot.logY));
      }
  if (!std::isfinite(r.xMin)) throw AnalysisError("line plot '" + plot.title + "' has no drawable points");
  return r;
}

// The frame with its x mapping from axis space onto the picture.
struct LineFrame {
  Frame f;
  double x0 = 0, x1 = 1;
  double x(double v) const { return f.left + (v - x0) / (x1 - x0) * (f.right - f.left); }
};

// One series: its line through the usable points, a dot on each, and its legend entry.
void drawSeries(cairo_t* cr, const LineFrame& lf, const LinePlot& plot, std::size_t k) {
  const Frame& f = lf.f;
  const auto& s = plot.series[k];
  const Rgb c = paletteColor(k);
  cairo_set_source_rgb(cr, c.r, c.g, c.b);
  cairo_set_line_width(cr, 2.0);
  bool first = true;
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (!usable(s.x[i], plot.logX) || !usable(s.y[i], plot.logY)) continue;
    const double x = lf.x(axis(s.x[i], plot.logX)), y = f.y(axis(s.y[i], plot.logY));
    if (first) cairo_move_to(cr, x, y);
    else cairo_line_to(cr, x, y);
    first = false;
  }
  cairo_stroke(cr);
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (!usable(s.x[i], plot.logX) || !usable(s.y[i], plot.logY)) continue;
    cairo_arc(cr, lf.x(axis(s.x[i], plot.logX)), f.y(axis(s.y[i], plot.logY)), 3.5, 0, 2 * M_PI);
    cairo_fill(cr);
  }
  const double ly = f.top + 18 * double(k);
  cairo_rectangle(cr, f.right + 14, ly - 8, 12, 10);
  cairo_fill(cr);
  drawText(cr, s.label, f.right + 32, ly + 1, 11, Align::Left);
}

}  // namespace

std::string renderLinePlotSvg(const LinePlot& plot, double width, double height) {
  const Range r = dataRange(plot);
  const auto xTicks = niceTicks(r.xMin, r.xMax), yTicks = niceTicks(r.yMin, r.yMax);
  SvgCanvas canvas(width, height);
  cairo_t* cr = canvas.cr();
  LineFrame lf{plotFrame(width, height, 170, 50), xTicks.front(), xTicks.back()};
  Frame& f = lf.f;
  f.yMin = yTicks.front();
  f.yMax = yTicks.back();
  drawText(cr, plot.title, width / 2, 22, 14, Align::Center, true);
  drawYGrid(cr, f, yTicks, plot.logY);
  for (const double t : xTicks)
    drawText(cr, plot.logX ? "1e" + tickLabel(t) : tickLabel(t), lf.x(t), f.bottom + 16, 11, Align::Center);
  drawAxisLines(cr, f, plot.yLabel);
  drawText(cr, plot.xLabel, (f.left + f.right) / 2, height - 12, 12, Align::Center);
  for (std::size_t k = 0; k < plot.series.size(); ++k) drawSeries(cr, lf, plot, k);
  return canvas.finish();
}

}  // namespace tlab::analysis
