#pragma once
// TextTable: a captioned grid of already formatted cells, the common form of every table that is
// shown to a person (terminal, HTML, Markdown).
#include <string>
#include <vector>

namespace tlab::analysis {

struct TextTable {
  std::string caption;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

// Columns padded to their widest cell, numbers right-aligned; caption on its own line.
std::string renderPlainText(const TextTable& table);
std::string renderHtmlTable(const TextTable& table);
std::string renderMarkdownTable(const TextTable& table);

}  // namespace tlab::analysis
