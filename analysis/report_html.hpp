#pragma once
// HTML rendering of a Report: one self-contained page (inline CSS; figures embedded as SVG
// data: URIs, so each plot is an isolated SVG document whose glyph ids cannot clash).
#include <string>

#include "analysis/report.hpp"

namespace tlab::analysis {

std::string renderHtml(const Report& report);

}  // namespace tlab::analysis
