#pragma once
// Statistical plots drawn with Cairo onto its SVG surface (cairo_svg_surface_create_for_stream),
// returned as SVG text: bar charts of cell means with error bars (the style of Elmqvist Figs. 9-10)
// and box plots per condition (Tukey's: box Q1-Q3, median, whiskers to the most extreme values
// inside the 1.5 IQR fences, points beyond them).
#include <limits>
#include <string>
#include <vector>

namespace tlab::analysis {

struct BarSeries {
  std::string label;            // legend entry (a level of the grouping factor), may be empty
  std::vector<double> means;    // one per category
  std::vector<double> errors;   // half-length of the error bar, one per category
};

struct BarChart {
  std::string title;
  std::string yLabel;
  std::string errorBarMeaning;  // e.g. "error bars: ±1 SD"
  std::vector<std::string> categories;  // x-axis groups
  std::vector<BarSeries> series;        // bars within each group
  // The scale's own limits, e.g. [0, 1] for a proportion: the axis never runs past them and error
  // bars are clipped to them (NaN: no limit).
  double yFloor = std::numeric_limits<double>::quiet_NaN();
  double yCeiling = std::numeric_limits<double>::quiet_NaN();
};

struct BoxPlotGroup {
  std::string label;
  std::vector<double> values;
};

struct BoxPlot {
  std::string title;
  std::string yLabel;
  std::vector<BoxPlotGroup> groups;
};

// Lines through (x, y) points, one per series, on linear or log10 axes (error-vs-time plots).
struct LineSeries {
  std::string label;
  std::vector<double> x, y;
};

struct LinePlot {
  std::string title;
  std::string xLabel, yLabel;
  bool logX = false, logY = false;
  std::vector<LineSeries> series;
};

std::string renderBarChartSvg(const BarChart& chart, double width = 640, double height = 400);
// The y-axis ticks of a bar chart: from 0 (or below) to the highest bar plus error, within the
// chart's yFloor/yCeiling.
std::vector<double> barChartTicks(const BarChart& chart);
std::string renderBoxPlotSvg(const BoxPlot& plot, double width = 640, double height = 400);
std::string renderLinePlotSvg(const LinePlot& plot, double width = 640, double height = 400);

// "Nice" axis ticks covering [lo, hi] (Heckbert 1990, "Nice numbers for graph labels",
// Graphics Gems I): steps of 1, 2 or 5 × 10^k, about `targetCount` of them.
std::vector<double> niceTicks(double lo, double hi, int targetCount = 6);

}  // namespace tlab::analysis
