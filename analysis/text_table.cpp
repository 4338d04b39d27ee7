#include "analysis/text_table.hpp"

#include <algorithm>
#include <cctype>

#include "analysis/number_format.hpp"

namespace tlab::analysis {

namespace {

// Display width of UTF-8 text (code points; enough for the labels used here).
std::size_t displayWidth(const std::string& s) {
  std::size_t n = 0;
  for (const char c : s)
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++n;
  return n;
}

bool looksNumeric(const std::string& s) {
  if (s.empty()) return false;
  for (const char c : s)
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' || c == 'e' ||
          c == '<' || c == ' ' || c == 'N' || c == 'A' || c == 'i' || c == 'n' || c == 'f'))
      return false;
  return std::any_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

std::string escapeMarkdown(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '|') out += "\\|";
    else out.push_back(c);
  }
  return out;
}

}  // namespace

const std::string& cellLink(const TextTable& table, std::size_t row, std::size_t column) {
  static const std::string none;
  if (row >= table.links.size() || column >= table.links[row].size()) return none;
  return table.links[row][column];
}

std::string renderPlainText(const TextTable& table) {
  std::vector<std::size_t> widths(table.header.size(), 0);
  for (std::size_t c = 0; c < table.header.size(); ++c) widths[c] = displayWidth(table.header[c]);
  for (const auto& row : table.rows)
    for (std::size_t c = 0; c < row.size() && c < widths.size(); ++c)
      widths[c] = std::max(widths[c], displayWidth(row[c]));
  std::string out;
  if (!table.caption.empty()) out += table.caption + "\n";
  const auto line = [&](const std::vector<std::string>& cells, bool header) {
    std::string s;
    for (std::size_t c = 0; c < widths.size(); ++c) {
      const std::string cell = c < cells.size() ? cells[c] : "";
      const std::string pad(widths[c] - displayWidth(cell), ' ');
      s += (c ? "  " : "  ");
      s += (!header && c > 0 && looksNumeric(cell)) ? pad + cell : cell + pad;
    }
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s + "\n";
  };
  out += line(table.header, true);
  std::string rule = "  ";
  for (std::size_t c = 0; c < widths.size(); ++c) rule += std::string(widths[c], '-') + (c + 1 < widths.size() ? "  " : "");
  out += rule + "\n";
  for (const auto& row : table.rows) out += line(row, false);
  return out;
}

std::string renderHtmlTable(const TextTable& table) {
  std::string out = "<table>\n";
  if (!table.caption.empty()) out += "<caption>" + escapeHtml(table.caption) + "</caption>\n";
  out += "<thead><tr>";
  for (const auto& h : table.header) out += "<th>" + escapeHtml(h) + "</th>";
  out += "</tr></thead>\n<tbody>\n";
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const auto& row = table.rows[r];
    out += "<tr>";
    for (std::size_t c = 0; c < row.size(); ++c) {
      const std::string& href = cellLink(table, r, c);
      const std::string cell = href.empty() ? escapeHtml(row[c]) : "<a href=\"" + escapeHtml(href) + "\">" + escapeHtml(row[c]) + "</a>";
      out += std::string(c > 0 && looksNumeric(row[c]) ? "<td class=\"num\">" : "<td>") + cell + "</td>";
    }
    out += "</tr>\n";
  }
  return out + "</tbody>\n</table>\n";
}

std::string renderMarkdownTable(const TextTable& table) {
  std::string out;
  if (!table.caption.empty()) out += "**" + escapeMarkdown(table.caption) + "**\n\n";
  out += "|";
  for (const auto& h : table.header) {
    out += ' ';
    out += escapeMarkdown(h);
    out += " |";
  }
  out += "\n|";
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    bool numeric = c > 0;
    for (const auto& row : table.rows)
      if (c < row.size() && !row[c].empty() && !looksNumeric(row[c])) numeric = false;
    out += numeric ? " ---: |" : " --- |";
  }
  out += "\n";
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    out += "|";
    for (std::size_t c = 0; c < table.rows[r].size(); ++c) {
      const std::string& href = cellLink(table, r, c);
      out += ' ';
      out += href.empty() ? escapeMarkdown(table.rows[r][c]) : "[" + escapeMarkdown(table.rows[r][c]) + "](" + href + ")";
      out += " |";
    }
    out += "\n";
  }
  return out + "\n";
}

}  // namespace tlab::analysis
