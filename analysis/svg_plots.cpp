#include "analysis/svg_plots.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "analysis/analysis_error.hpp"
#include "analysis/descriptives.hpp"

namespace tlab::analysis {

namespace {

struct Rgb {
  double r, g, b;
};
// Colour-blind-safe qualitative palette (Okabe & Ito 2008).
constexpr Rgb kPalette[] = {{0.000, 0.447, 0.698}, {0.902, 0.624, 0.000}, {0.000, 0.620, 0.451},
                            {0.800, 0.475, 0.655}, {0.337, 0.706, 0.914}, {0.835, 0.369, 0.000},
                            {0.941, 0.894, 0.259}};
Rgb paletteColor(std::size_t i) { return kPalette[i % (sizeof kPalette / sizeof kPalette[0])]; }

cairo_status_t appendToString(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// An SVG surface writing into a string; finish() flushes and returns the document.
class SvgCanvas {
 public:
  SvgCanvas(double width, double height)
      : surface_(cairo_svg_surface_create_for_stream(appendToString, &svg_, width, height)),
        cr_(cairo_create(surface_)) {
    cairo_select_font_face(cr_, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_source_rgb(cr_, 1, 1, 1);
    cairo_paint(cr_);
  }
  ~SvgCanvas() {
    if (cr_) cairo_destroy(cr_);
    if (surface_) cairo_surface_destroy(surface_);
  }
  SvgCanvas(const SvgCanvas&) = delete;
  SvgCanvas& operator=(const SvgCanvas&) = delete;

  cairo_t* cr() const { return cr_; }

  std::string finish() {
    const cairo_status_t status = cairo_status(cr_);
    cairo_destroy(cr_);
    cr_ = nullptr;
    cairo_surface_finish(surface_);
    const cairo_status_t surfaceStatus = cairo_surface_status(surface_);
    cairo_surface_destroy(surface_);
    surface_ = nullptr;
    if (status != CAIRO_STATUS_SUCCESS || surfaceStatus != CAIRO_STATUS_SUCCESS)
      throw AnalysisError(std::string("cairo SVG drawing failed: ") +
                          cairo_status_to_string(status != CAIRO_STATUS_SUCCESS ? status : surfaceStatus));
    return svg_;
  }

 private:
  std::string svg_;
  cairo_surface_t* surface_;
  cairo_t* cr_;
};

enum class Align { Left, Center, Right };

void drawText(cairo_t* cr, const std::string& text, double x, double y, double size, Align align,
              bool bold = false, double angle = 0.0) {
  cairo_save(cr);
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, text.c_str(), &ext);
  cairo_translate(cr, x, y);
  cairo_rotate(cr, angle);
  const double dx = align == Align::Left ? 0.0 : (align == Align::Center ? -ext.x_advance / 2 : -ext.x_advance);
  cairo_move_to(cr, dx, 0);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_show_text(cr, text.c_str());
  cairo_restore(cr);
}

std::string tickLabel(double v) {
  std::ostringstream out;
  out.precision(6);
  out << (std::fabs(v) < 1e-12 ? 0.0 : v);
  return out.str();
}

// Plot area and the y mapping shared by both plot kinds.
struct Frame {
  double left = 70, right = 0, top = 40, bottom = 0;
  double yMin = 0, yMax = 1;
  double y(double v) const { return bottom - (v - yMin) / (yMax - yMin) * (bottom - top); }
};

// The plot area of a width × height picture, leaving `rightMargin` and `bottomMargin` free.
Frame plotFrame(double width, double height, double rightMargin, double bottomMargin) {
  Frame f;
  f.right = width - rightMargin;
  f.bottom = height - bottomMargin;
  return f;
}

void drawYAxis(cairo_t* cr, const Frame& f, const std::vector<double>& ticks, const std::string& label) {
  cairo_set_line_width(cr, 1.0);
  for (const double t : ticks) {
    const double y = f.y(t);
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, f.left, y);
    cairo_line_to(cr, f.right, y);
    cairo_stroke(cr);
    drawText(cr, tickLabel(t), f.left - 6, y + 4, 11, Align::Right);
  }
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_move_to(cr, f.left, f.top);
  cairo_line_to(cr, f.left, f.bottom);
  cairo_line_to(cr, f.right, f.bottom);
  cairo_stroke(cr);
  drawText(cr, label, 18, (f.top + f.bottom) / 2, 12, Align::Center, false, -M_PI / 2);
}

double niceNumber(double x, bool round) {
  const double exponent = std::floor(std::log10(x));
  const double fraction = x / std::pow(10.0, exponent);
  double nice = 10;
  if (round)
    nice = fraction < 1.5 ? 1 : fraction < 3 ? 2 : fraction < 7 ? 5 : 10;
  else
    nice = fraction <= 1 ? 1 : fraction <= 2 ? 2 : fraction <= 5 ? 5 : 10;
  return nice * std::pow(10.0, exponent);
}

}  // namespace

std::vector<double> niceTicks(double lo, double hi, int targetCount) {
  if (!(hi > lo)) {
    const double pad = lo == 0 ? 1.0 : std::fabs(lo) * 0.1;
    lo -= pad;
    hi += pad;
  }
  const double range = niceNumber(hi - lo, false);
  const double step = niceNumber(range / std::max(1, targetCount - 1), true);
  std::vector<double> ticks;
  for (double t = std::floor(lo / step) * step; t <= std::ceil(hi / step) * step + 0.5 * step; t += step)
    ticks.push_back(t);
  return ticks;
}

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
  Frame f = plotFrame(width, height, 20, 70);
  const std::vector<double> ticks = barChartTicks(chart);
  f.yMin = ticks.front();
  f.yMax = ticks.back();
  drawText(cr, chart.title, width / 2, 22, 14, Align::Center, true);
  drawYAxis(cr, f, ticks, chart.yLabel);

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
      if (g < series.errors.size() && std::isfinite(series.errors[g])) {
        const double cx = x + barWidth / 2;
        const double ylo = f.y(std::max(f.yMin, series.means[g] - series.errors[g]));
        const double yhi = f.y(std::min(f.yMax, series.means[g] + series.errors[g]));
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
    }
    drawText(cr, chart.categories[g], f.left + groupWidth * (static_cast<double>(g) + 0.5), f.bottom + 18, 12,
             Align::Center);
  }
  // Legend and error-bar note under the axis.
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
  return canvas.finish();
}

std::string renderBoxPlotSvg(const BoxPlot& plot, double width, double height) {
  SvgCanvas canvas(width, height);
  cairo_t* cr = canvas.cr();
  Frame f = plotFrame(width, height, 20, 50);
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
  const std::vector<double> ticks = niceTicks(lo, hi);
  f.yMin = ticks.front();
  f.yMax = ticks.back();
  drawText(cr, plot.title, width / 2, 22, 14, Align::Center, true);
  drawYAxis(cr, f, ticks, plot.yLabel);
  const double slot = (f.right - f.left) / static_cast<double>(std::max<std::size_t>(1, plot.groups.size()));
  for (std::size_t i = 0; i < plot.groups.size(); ++i) {
    const auto& g = plot.groups[i];
    const double cx = f.left + slot * (static_cast<double>(i) + 0.5);
    drawText(cr, g.label, cx, f.bottom + 18, 11, Align::Center);
    if (g.values.empty()) continue;
    std::vector<double> v = g.values;
    std::sort(v.begin(), v.end());
    const double q1 = quantileType7(v, 0.25);
    const double med = quantileType7(v, 0.5);
    const double q3 = quantileType7(v, 0.75);
    const double lowFence = q1 - 1.5 * (q3 - q1);
    const double highFence = q3 + 1.5 * (q3 - q1);
    double whiskerLow = q1;
    double whiskerHigh = q3;
    for (const double x : v) {
      if (x >= lowFence) whiskerLow = std::min(whiskerLow, x);
      if (x <= highFence) whiskerHigh = std::max(whiskerHigh, x);
    }
    const double half = std::min(40.0, slot * 0.3);
    const Rgb c = paletteColor(i);
    cairo_set_source_rgba(cr, c.r, c.g, c.b, 0.35);
    cairo_rectangle(cr, cx - half, f.y(q3), 2 * half, f.y(q1) - f.y(q3));
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, c.r * 0.7, c.g * 0.7, c.b * 0.7);
    cairo_set_line_width(cr, 1.5);
    cairo_stroke(cr);
    cairo_set_line_width(cr, 2.5);
    cairo_move_to(cr, cx - half, f.y(med));
    cairo_line_to(cr, cx + half, f.y(med));
    cairo_stroke(cr);
    cairo_set_line_width(cr, 1.2);
    cairo_move_to(cr, cx, f.y(q3));
    cairo_line_to(cr, cx, f.y(whiskerHigh));
    cairo_move_to(cr, cx, f.y(q1));
    cairo_line_to(cr, cx, f.y(whiskerLow));
    cairo_move_to(cr, cx - half / 2, f.y(whiskerHigh));
    cairo_line_to(cr, cx + half / 2, f.y(whiskerHigh));
    cairo_move_to(cr, cx - half / 2, f.y(whiskerLow));
    cairo_line_to(cr, cx + half / 2, f.y(whiskerLow));
    cairo_stroke(cr);
    for (const double x : v)
      if (x < lowFence || x > highFence) {
        cairo_arc(cr, cx, f.y(x), 3.0, 0, 2 * M_PI);
        cairo_stroke(cr);
      }
  }
  return canvas.finish();
}

std::string renderLinePlotSvg(const LinePlot& plot, double width, double height) {
  // Values are drawn in axis space: log10 of the value on a log axis (non-positive values skipped).
  const auto axis = [](double v, bool log) { return log ? std::log10(v) : v; };
  const auto usable = [](double v, bool log) { return std::isfinite(v) && (!log || v > 0); };
  double xMin = INFINITY, xMax = -INFINITY, yMin = INFINITY, yMax = -INFINITY;
  for (const auto& s : plot.series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (usable(s.x[i], plot.logX) && usable(s.y[i], plot.logY)) {
        xMin = std::min(xMin, axis(s.x[i], plot.logX));
        xMax = std::max(xMax, axis(s.x[i], plot.logX));
        yMin = std::min(yMin, axis(s.y[i], plot.logY));
        yMax = std::max(yMax, axis(s.y[i], plot.logY));
      }
  if (!std::isfinite(xMin)) throw AnalysisError("line plot '" + plot.title + "' has no drawable points");
  const auto xTicks = niceTicks(xMin, xMax), yTicks = niceTicks(yMin, yMax);
  SvgCanvas canvas(width, height);
  cairo_t* cr = canvas.cr();
  Frame f = plotFrame(width, height, 170, 50);
  f.yMin = yTicks.front();
  f.yMax = yTicks.back();
  const double x0 = xTicks.front(), x1 = xTicks.back();
  const auto px = [&](double v) { return f.left + (v - x0) / (x1 - x0) * (f.right - f.left); };
  const auto label = [](double v, bool log) { return log ? "1e" + tickLabel(v) : tickLabel(v); };
  drawText(cr, plot.title, width / 2, 22, 14, Align::Center, true);
  cairo_set_line_width(cr, 1.0);
  for (const double t : yTicks) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, f.left, f.y(t));
    cairo_line_to(cr, f.right, f.y(t));
    cairo_stroke(cr);
    drawText(cr, label(t, plot.logY), f.left - 6, f.y(t) + 4, 11, Align::Right);
  }
  for (const double t : xTicks) drawText(cr, label(t, plot.logX), px(t), f.bottom + 16, 11, Align::Center);
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_move_to(cr, f.left, f.top);
  cairo_line_to(cr, f.left, f.bottom);
  cairo_line_to(cr, f.right, f.bottom);
  cairo_stroke(cr);
  drawText(cr, plot.yLabel, 18, (f.top + f.bottom) / 2, 12, Align::Center, false, -M_PI / 2);
  drawText(cr, plot.xLabel, (f.left + f.right) / 2, height - 12, 12, Align::Center);
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const auto& s = plot.series[k];
    const Rgb c = paletteColor(k);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_set_line_width(cr, 2.0);
    bool first = true;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!usable(s.x[i], plot.logX) || !usable(s.y[i], plot.logY)) continue;
      const double x = px(axis(s.x[i], plot.logX)), y = f.y(axis(s.y[i], plot.logY));
      if (first) cairo_move_to(cr, x, y);
      else cairo_line_to(cr, x, y);
      first = false;
    }
    cairo_stroke(cr);
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!usable(s.x[i], plot.logX) || !usable(s.y[i], plot.logY)) continue;
      cairo_arc(cr, px(axis(s.x[i], plot.logX)), f.y(axis(s.y[i], plot.logY)), 3.5, 0, 2 * M_PI);
      cairo_fill(cr);
    }
    const double ly = f.top + 18 * double(k);
    cairo_rectangle(cr, f.right + 14, ly - 8, 12, 10);
    cairo_fill(cr);
    drawText(cr, s.label, f.right + 32, ly + 1, 11, Align::Left);
  }
  return canvas.finish();
}

}  // namespace tlab::analysis
