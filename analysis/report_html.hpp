#pragma once
// HTML rendering of a Report: one self-contained page (inline CSS; figures embedded as SVG
// data: URIs, so each plot is an isolated SVG document whose glyph ids cannot clash).
#include <string>

#include <vector>

#include "analysis/report.hpp"
#include "analysis/text_table.hpp"

namespace tlab::analysis {

std::string renderHtml(const Report& report);

// Several reports on one page (a whole study: one report per planned analysis), after an
// introduction: paragraphs, a gallery of images (e.g. the stimuli, as PNG bytes) and summary tables.
struct PageImage {
  std::string caption;
  std::string mimeType;  // "image/png"
  std::string bytes;
};

struct ReportPage {
  std::string title;
  std::vector<std::string> paragraphs;
  std::vector<PageImage> images;
  int imageWidth = 220;  // CSS pixels per gallery image
  std::vector<TextTable> tables;
  std::vector<Report> reports;
};

std::string renderHtml(const ReportPage& page);

}  // namespace tlab::analysis
