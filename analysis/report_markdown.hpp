#pragma once
// Markdown rendering of a Report (GitHub-flavoured pipe tables). Figures cannot be embedded
// portably in Markdown, so they are returned as separate SVG files that the text links to.
#include <string>
#include <vector>

#include "analysis/report.hpp"

namespace tlab::analysis {

struct MarkdownDocument {
  struct FigureFile {
    std::string fileName;  // relative to the Markdown file
    std::string svg;
  };
  std::string text;
  std::vector<FigureFile> figures;
};

// `figureStem` prefixes the figure file names: "<stem>_fig1.svg", ...
MarkdownDocument renderMarkdown(const Report& report, const std::string& figureStem);

}  // namespace tlab::analysis
