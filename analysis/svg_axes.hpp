#pragma once
// What the SVG plots (svg_bar_chart.cpp, svg_box_plot.cpp, svg_line_plot.cpp) share: a Cairo SVG
// surface writing into a string, the Okabe-Ito palette, text, the plot frame and its y axis.
// Internal to analysis/; the plots themselves are declared in svg_plots.hpp.
#include <cairo.h>

#include <cstddef>
#include <string>
#include <vector>

namespace tlab::analysis::svg {

struct Rgb {
  double r, g, b;
};
// Colour-blind-safe qualitative palette (Okabe & Ito 2008), repeating after seven colours.
Rgb paletteColor(std::size_t i);

// An SVG surface writing into a string; finish() flushes and returns the document.
class SvgCanvas {
 public:
  SvgCanvas(double width, double height);
  ~SvgCanvas();
  SvgCanvas(const SvgCanvas&) = delete;
  SvgCanvas& operator=(const SvgCanvas&) = delete;

  cairo_t* cr() const { return cr_; }
  std::string finish();

 private:
  std::string svg_;
  cairo_surface_t* surface_;
  cairo_t* cr_;
};

enum class Align { Left, Center, Right };

void drawText(cairo_t* cr, const std::string& text, double x, double y, double size, Align align,
              bool bold = false, double angle = 0.0);

std::string tickLabel(double v);

// Plot area and the y mapping shared by every plot kind.
struct Frame {
  double left = 70, right = 0, top = 40, bottom = 0;
  double yMin = 0, yMax = 1;
  double y(double v) const { return bottom - (v - yMin) / (yMax - yMin) * (bottom - top); }
};

// The plot area of a width × height picture, leaving `rightMargin` and `bottomMargin` free.
Frame plotFrame(double width, double height, double rightMargin, double bottomMargin);

// Horizontal grid lines at the y ticks, each labelled on the left ("1e<tick>" on a log axis).
void drawYGrid(cairo_t* cr, const Frame& f, const std::vector<double>& ticks, bool logLabels = false);
// The left and bottom axis lines and the rotated y-axis label.
void drawAxisLines(cairo_t* cr, const Frame& f, const std::string& yLabel);
// The frame of a plot whose y axis runs over `ticks` (linear, no x ticks), with the title, the y
// grid and the axis lines drawn.
Frame drawPlotFrame(cairo_t* cr, double width, double height, double rightMargin, double bottomMargin,
                    const std::vector<double>& ticks, const std::string& title, const std::string& yLabel);

}  // namespace tlab::analysis::svg
