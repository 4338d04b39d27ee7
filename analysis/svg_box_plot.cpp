// Tukey box plots per condition (svg_plots.hpp), drawn on the shared axes (svg_axes.hpp).
#include <algorithm>
#include <cmath>

#include "analysis/descriptives.hpp"
#include "analysis/svg_axes.hpp"
#include "analysis/svg_plots.hpp"

namespace tlab::analysis {

namespace {

using namespace svg;

// Ticks over every group's values ([0, 1] when there are none).
std::vector<double> boxPlotTicks(const BoxPlot& plot) {
  double lo = INFINITY;
  double hi = -INFINITY;
  for (const auto& g : plot.groups)
    for (const double v : g.values) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  if (!std::isfinite(lo)) {
    lo = 0;
    hi = 1;
  }
  return niceTicks(lo, hi);
}

// Tukey's box of sorted values: quartiles, the 1.5 IQR fences and the whiskers inside them.
struct TukeyBox {
  double q1, med, q3, lowFence, highFence, whiskerLow, whiskerHigh;
};

TukeyBox tukeyBox(const std::vector<double>& sorted) {
  TukeyBox b;
  b.q1 = quantileType7(sorted, 0.25);
  b.med = quantileType7(sorted, 0.5);
  b.q3 = quantileType7(sorted, 0.75);
  b.lowFence = b.q1 - 1.5 * (b.q3 - b.q1);
  b.highFence = b.q3 + 1.5 * (b.q3 - b.q1);
  b.whiskerLow = b.q1;
  b.whiskerHigh = b.q3;
  for (const double x : sorted) {
    if (x >= b.lowFence) b.whiskerLow = std::min(b.whiskerLow, x);
    if (x <= b.highFence) b.whiskerHigh = std::max(b.whiskerHigh, x);
  }
  return b;
}

// The box, its median line, the whiskers and the points beyond the fences.
void drawBox(cairo_t* cr, const Frame& f, double cx, double half, const Rgb& c, const TukeyBox& b,
             const std::vector<double>& sorted) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, 0.35);
  cairo_rectangle(cr, cx - half, f.y(b.q3), 2 * half, f.y(b.q1) - f.y(b.q3));
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, c.r * 0.7, c.g * 0.7, c.b * 0.7);
  cairo_set_line_width(cr, 1.5);
  cairo_stroke(cr);
  cairo_set_line_width(cr, 2.5);
  cairo_move_to(cr, cx - half, f.y(b.med));
  cairo_line_to(cr, cx + half, f.y(b.med));
  cairo_stroke(cr);
  cairo_set_line_width(cr, 1.2);
  cairo_move_to(cr, cx, f.y(b.q3));
  cairo_line_to(cr, cx, f.y(b.whiskerHigh));
  cairo_move_to(cr, cx, f.y(b.q1));
  cairo_line_to(cr, cx, f.y(b.whiskerLow));
  cairo_move_to(cr, cx - half / 2, f.y(b.whiskerHigh));
  cairo_line_to(cr, cx + half / 2, f.y(b.whiskerHigh));
  cairo_move_to(cr, cx - half / 2, f.y(b.whiskerLow));
  cairo_line_to(cr, cx + half / 2, f.y(b.whiskerLow));
  cairo_stroke(cr);
  for (const double x : sorted)
    if (x < b.lowFence || x > b.highFence) {
      cairo_arc(cr, cx, f.y(x), 3.0, 0, 2 * M_PI);
      cairo_stroke(cr);
    }
}

}  // namespace

std::string renderBoxPlotSvg(const BoxPlot& plot, double width, double height) {
  SvgCanvas canvas(width, height);
  cairo_t* cr = canvas.cr();
  const Frame f = drawPlotFrame(cr, width, height, 20, 50, boxPlotTicks(plot), plot.title, plot.yLabel);
  const double slot = (f.right - f.left) / static_cast<double>(std::max<std::size_t>(1, plot.groups.size()));
  for (std::size_t i = 0; i < plot.groups.size(); ++i) {
    const auto& g = plot.groups[i];
    const double cx = f.left + slot * (static_cast<double>(i) + 0.5);
    drawText(cr, g.label, cx, f.bottom + 18, 11, Align::Center);
    if (g.values.empty()) continue;
    std::vector<double> v = g.values;
    std::sort(v.begin(), v.end());
    drawBox(cr, f, cx, std::min(40.0, slot * 0.3), paletteColor(i), tukeyBox(v), v);
  }
  return canvas.finish();
}

}  // namespace tlab::analysis
