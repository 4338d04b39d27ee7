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
.warning { border: 2px solid #c60; background: #fff4e5; padding: .6em .9em; }
.gallery { display: flex; flex-wrap: wrap; gap: .5em; } .gallery figure { margin: 0; }
)";

std::string section(const TextTable& table, const std::string& whenEmpty) {
  if (table.rows.empty()) return whenEmpty.empty() ? "" : "<p class=\"note\">" + escapeHtml(whenEmpty) + "</p>\n";
  return renderHtmlTable(table);
}

}  // namespace

namespace {

std::string head(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escapeHtml(title) + "</title>\n<style>" +
         kStyle + "</style>\n</head>\n<body>\n";
}

std::string heading(int level, const std::string& text) {
  const std::string tag = "h" + std::to_string(level);
  return "<" + tag + ">" + escapeHtml(text) + "</" + tag + ">\n";
}

std::string image(const std::string& caption, const std::string& mimeType, const std::string& bytes, const std::string& style = "") {
  return "<figure><img alt=\"" + escapeHtml(caption) + "\"" + (style.empty() ? "" : " style=\"" + style + "\"") + " src=\"data:" +
         mimeType + ";base64," + base64Encode(bytes) + "\"><figcaption>" + escapeHtml(caption) + "</figcaption></figure>\n";
}

// One report's sections, its title at heading `level` and each dependent variable one below.
std::string body(const Report& report, int level) {
  std::string html = heading(level, report.title);
  for (const auto& warning : report.warnings) html += "<p class=\"warning\">" + escapeHtml(warning) + "</p>\n";
  html += renderHtmlTable(designTable(report));
  for (const auto& note : report.notes) html += "<p class=\"note\">" + escapeHtml(note) + "</p>\n";
  for (const auto& dv : report.dependentVariables) {
    html += heading(level + 1, dv.dv);
    html += renderHtmlTable(descriptivesTable(dv));
    html += section(outlierTable(dv), "Outlier screening: no value beyond the Tukey fences or with |z| > 3.");
    if (dv.anova) {
      html += renderHtmlTable(anovaTable(*dv.anova));
      html += section(sphericityTable(*dv.anova), "");
    } else if (!dv.anovaError.empty()) {
      html += "<p class=\"error\">ANOVA not computed: " + escapeHtml(dv.anovaError) + "</p>\n";
    }
    html += section(comparisonTable(dv.comparisons), "");
    for (const auto& figure : dv.figures) html += image(figure.caption, "image/svg+xml", figure.svg);
  }
  for (const auto& s : report.sections) {
    html += heading(level + 1, s.heading);
    for (const auto& p : s.paragraphs) html += "<p>" + escapeHtml(p) + "</p>\n";
    for (const auto& w : s.warnings) html += "<p class=\"warning\">" + escapeHtml(w) + "</p>\n";
    for (const auto& table : s.tables) html += renderHtmlTable(table);
  }
  for (const auto& table : report.appendices) html += renderHtmlTable(table);
  if (!report.images.empty()) {
    html += "<div class=\"gallery\">\n";
    for (const auto& i : report.images) html += image(i.caption, i.mimeType, i.bytes, "width: 220px");
    html += "</div>\n";
  }
  return html;
}

}  // namespace

std::string renderHtml(const Report& report) { return head(report.title) + body(report, 1) + "</body>\n</html>\n"; }

std::string renderHtml(const ReportPage& page) {
  std::string html = head(page.title) + heading(1, page.title);
  for (const auto& p : page.paragraphs) html += "<p>" + escapeHtml(p) + "</p>\n";
  if (!page.images.empty()) {
    html += "<div class=\"gallery\">\n";
    for (const auto& i : page.images) html += image(i.caption, i.mimeType, i.bytes, "width: " + std::to_string(page.imageWidth) + "px");
    html += "</div>\n";
  }
  for (const auto& table : page.tables) html += renderHtmlTable(table);
  for (const auto& report : page.reports) html += body(report, 2);
  return html + "</body>\n</html>\n";
}

}  // namespace tlab::analysis
