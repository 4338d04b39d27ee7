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
  // Optional: where a cell links to (a URL relative to the page), in the shape of `rows`; an empty
  // or missing entry is no link. HTML and Markdown show the link; plain text shows the cell alone.
  std::vector<std::vector<std::string>> links{};
};

// The link of cell (row, column), "" when it has none.
const std::string& cellLink(const TextTable& table, std::size_t row, std::size_t column);

// Columns padded to their widest cell, numbers right-aligned; caption on its own line.
std::string renderPlainText(const TextTable& table);
std::string renderHtmlTable(const TextTable& table);
std::string renderMarkdownTable(const TextTable& table);

}  // namespace tlab::analysis
