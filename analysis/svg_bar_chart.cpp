// Bar charts of cell means with error bars (svg_plots.hpp), drawn on the shared axes (svg_axes.hpp).
#include <algorithm>
#include <cmath>

#include "analysis/svg_axes.hpp"
#include "analysis/svg_plots.hpp"

namespace tlab::analysis {

namespace {

using namespace svg;

void drawErrorBar(cairo_t* cr, const Frame& f, double cx, double barWidth, double mean, double error) {
  const double ylo = f.y(std::max(f.yMin, mean - error));
  const double yhi = f.y(std::min(f.yMax, mean + error));
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_set_line_width(cr, 1.5);
  cairo_move_to(cr, cx, ylo);
  cairo_line_to(cr, cx, yhi);
  cairo_move_to(cr, cx - barWidth * 0.2, ylo);
  cairo_line_to(cr, cx + barWidth * 0.2, ylo);
  cairo_move_to(cr, cx - barWidth * 0.2, yhi);
  cairo_line_to(cr, cx + barWidth * 0.2, yhi);
  cairo_stroke(cr);
}

// Each category's group of bars, one per series, with its error bar and the category's name.
void drawBars(cairo_t* cr, const Frame& f, const BarChart& chart) {
  const std::size_t groups = chart.categories.size();
  const std::size_t perGroup = std::max<std::size_t>(1, chart.series.size());
  const double groupWidth = (f.right - f.left) / static_cast<double>(std::max<std::size_t>(1, groups));
  const double barWidth = groupWidth * 0.7 / static_cast<double>(perGroup);
  for (std::size_t g = 0; g < groups; ++g) {
    const double groupLeft = f.left + groupWidth * static_cast<double>(g) + groupWidth * 0.15;
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
      const auto& series = chart.series[s];
      if (g >= series.means.size()) continue;
      const double x = groupLeft + barWidth * static_cast<double>(s);
      const double y0 = f.y(std::max(0.0, f.yMin));
      const double y1 = f.y(series.means[g]);
      const Rgb c = paletteColor(s);
      cairo_set_source_rgb(cr, c.r, c.g, c.b);
      cairo_rectangle(cr, x + 2, std::min(y0, y1), barWidth - 4, std::fabs(y0 - y1));
      cairo_fill(cr);
      if (g < series.errors.size() && std::isfinite(series.errors[g]))
        drawErrorBar(cr, f, x + barWidth / 2, barWidth, series.means[g], series.errors[g]);
    }
    drawText(cr, chart.categories[g], f.left + groupWidth * (static_cast<double>(g) + 0.5), f.bottom + 18, 12,
             Align::Center);
  }
}

// Legend and error-bar note under the axis.
void drawLegend(cairo_t* cr, const Frame& f, const BarChart& chart) {
  double lx = f.left;
  for (std::size_t s = 0; s < chart.series.size(); ++s) {
    if (chart.series[s].label.empty()) continue;
    const Rgb c = paletteColor(s);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_rectangle(cr, lx, f.bottom + 34, 12, 12);
    cairo_fill(cr);
    drawText(cr, chart.series[s].label, lx + 16, f.bottom + 44, 11, Align::Left);
    lx += 30 + 7.0 * static_cast<double>(chart.series[s].label.size());
  }
  drawText(cr, chart.errorBarMeaning, f.right, f.bottom + 62, 10, Align::Right);
}

}  // namespace

std::vector<double> barChartTicks(const BarChart& chart) {
  double top = 0.0;
  double low = 0.0;
  for (const auto& s : chart.series)
    for (std::size_t i = 0; i < s.means.size(); ++i) {
      const double e = i < s.errors.size() && std::isfinite(s.errors[i]) ? s.errors[i] : 0.0;
      top = std::max(top, s.means[i] + e);
      low = std::min(low, s.means[i] - e);
    }
  if (std::isfinite(chart.yCeiling)) top = std::min(top, chart.yCeiling);
  if (std::isfinite(chart.yFloor)) low = std::max(low, chart.yFloor);
  std::vector<double> ticks = niceTicks(low, top);
  std::erase_if(ticks, [&](double t) { return t > chart.yCeiling + 1e-12 || t < chart.yFloor - 1e-12; });
  return ticks;
}

std::string renderBarChartSvg(const BarChart& chart, double width, double height) {
  SvgCanvas canvas(width, height);
  cairo_t* cr = canvas.cr();
  const Frame f = drawPlotFrame(cr, width, height, 20, 70, barChartTicks(chart), chart.title, chart.yLabel);
  drawBars(cr, f, chart);
  drawLegend(cr, f, chart);
  return canvas.finish();
}

}  // namespace tlab::analysis
