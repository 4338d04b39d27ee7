#include "analysis/report_html.hpp"

#include "analysis/number_format.hpp"
#include "analysis/report_tables.hpp"

namespace tlab::analysis {

namespace {

constexpr const char* kStyle = R"(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; max-width: 70em; margin: 2em auto; color: #222; }
h1 { font-size: 1.6em; } h2 { border-bottom: 1px solid #ccc; padding-bottom: .2em; }
table { border-collapse: collapse; margin: 1em 0; }
caption { text-align: left; font-weight: bold; padding-bottom: .3em; }
th, td { border-bottom: 1px solid #ddd; padding: .25em .7em; text-align: left; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
figure { margin: 1em 0; } figcaption { font-size: .9em; color: #555; }
.error { color: #a00; } .note { color: #555; font-size: .95em; }
)";

std::string section(const TextTable& table, const std::string& whenEmpty) {
  if (table.rows.empty()) return whenEmpty.empty() ? "" : "<p class=\"note\">" + escapeHtml(whenEmpty) + "</p>\n";
  return renderHtmlTable(table);
}

}  // namespace

std::string renderHtml(const Report& report) {
  std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
                     escapeHtml(report.title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
  html += "<h1>" + escapeHtml(report.title) + "</h1>\n";
  html += renderHtmlTable(designTable(report));
  for (const auto& note : report.notes) html += "<p class=\"note\">" + escapeHtml(note) + "</p>\n";
  for (const auto& dv : report.dependentVariables) {
    html += "<h2>" + escapeHtml(dv.dv) + "</h2>\n";
    html += renderHtmlTable(descriptivesTable(dv));
    html += section(outlierTable(dv), "Outlier screening: no value beyond the Tukey fences or with |z| > 3.");
    if (dv.anova) {
      html += renderHtmlTable(anovaTable(*dv.anova));
      html += section(sphericityTable(*dv.anova), "");
    } else if (!dv.anovaError.empty()) {
      html += "<p class=\"error\">ANOVA not computed: " + escapeHtml(dv.anovaError) + "</p>\n";
    }
    html += section(comparisonTable(dv.comparisons), "");
    for (const auto& figure : dv.figures)
      html += "<figure><img alt=\"" + escapeHtml(figure.caption) + "\" src=\"data:image/svg+xml;base64," +
              base64Encode(figure.svg) + "\"><figcaption>" + escapeHtml(figure.caption) + "</figcaption></figure>\n";
  }
  html += "</body>\n</html>\n";
  return html;
}

}  // namespace tlab::analysis
