// The canvas, palette, text and axes shared by the SVG plots, and niceTicks (svg_plots.hpp).
#include "analysis/svg_axes.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/analysis_error.hpp"
#include "analysis/svg_plots.hpp"

namespace tlab::analysis {

namespace svg {

namespace {

constexpr Rgb kPalette[] = {{0.000, 0.447, 0.698}, {0.902, 0.624, 0.000}, {0.000, 0.620, 0.451},
                            {0.800, 0.475, 0.655}, {0.337, 0.706, 0.914}, {0.835, 0.369, 0.000},
                            {0.941, 0.894, 0.259}};

cairo_status_t appendToString(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

Rgb paletteColor(std::size_t i) { return kPalette[i % (sizeof kPalette / sizeof kPalette[0])]; }

SvgCanvas::SvgCanvas(double width, double height)
    : surface_(cairo_svg_surface_create_for_stream(appendToString, &svg_, width, height)),
      cr_(cairo_create(surface_)) {
  cairo_select_font_face(cr_, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_source_rgb(cr_, 1, 1, 1);
  cairo_paint(cr_);
}

SvgCanvas::~SvgCanvas() {
  if (cr_) cairo_destroy(cr_);
  if (surface_) cairo_surface_destroy(surface_);
}

std::string SvgCanvas::finish() {
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

void drawText(cairo_t* cr, const std::string& text, double x, double y, double size, Align align, bool bold,
              double angle) {
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

Frame plotFrame(double width, double height, double rightMargin, double bottomMargin) {
  Frame f;
  f.right = width - rightMargin;
  f.bottom = height - bottomMargin;
  return f;
}

void drawYGrid(cairo_t* cr, const Frame& f, const std::vector<double>& ticks, bool logLabels) {
  cairo_set_line_width(cr, 1.0);
  for (const double t : ticks) {
    const double y = f.y(t);
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, f.left, y);
    cairo_line_to(cr, f.right, y);
    cairo_stroke(cr);
    drawText(cr, logLabels ? "1e" + tickLabel(t) : tickLabel(t), f.left - 6, y + 4, 11, Align::Right);
  }
}

void drawAxisLines(cairo_t* cr, const Frame& f, const std::string& yLabel) {
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_move_to(cr, f.left, f.top);
  cairo_line_to(cr, f.left, f.bottom);
  cairo_line_to(cr, f.right, f.bottom);
  cairo_stroke(cr);
  drawText(cr, yLabel, 18, (f.top + f.bottom) / 2, 12, Align::Center, false, -M_PI / 2);
}

Frame drawPlotFrame(cairo_t* cr, double width, double height, double rightMargin, double bottomMargin,
                    const std::vector<double>& ticks, const std::string& title, const std::string& yLabel) {
  Frame f = plotFrame(width, height, rightMargin, bottomMargin);
  f.yMin = ticks.front();
  f.yMax = ticks.back();
  drawText(cr, title, width / 2, 22, 14, Align::Center, true);
  drawYGrid(cr, f, ticks);
  drawAxisLines(cr, f, yLabel);
  return f;
}

}  // namespace svg

namespace {

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

}  // namespace tlab::analysis
