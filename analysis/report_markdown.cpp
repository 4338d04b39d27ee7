#include "analysis/report_markdown.hpp"

#include "analysis/report_tables.hpp"

namespace tlab::analysis {

MarkdownDocument renderMarkdown(const Report& report, const std::string& figureStem) {
  MarkdownDocument doc;
  std::string& md = doc.text;
  md += "# " + report.title + "\n\n";
  for (const auto& warning : report.warnings) md += "> **" + warning + "**\n\n";
  md += renderMarkdownTable(designTable(report));
  for (const auto& note : report.notes) md += "_" + note + "_\n\n";
  for (const auto& dv : report.dependentVariables) {
    md += "## " + dv.dv + "\n\n";
    md += renderMarkdownTable(descriptivesTable(dv));
    const TextTable outliers = outlierTable(dv);
    md += outliers.rows.empty() ? "Outlier screening: no value beyond the Tukey fences or with |z| > 3.\n\n"
                                : renderMarkdownTable(outliers);
    if (dv.anova) {
      md += renderMarkdownTable(anovaTable(*dv.anova));
      const TextTable sphericity = sphericityTable(*dv.anova);
      if (!sphericity.rows.empty()) md += renderMarkdownTable(sphericity);
    } else if (!dv.anovaError.empty()) {
      md += "**ANOVA not computed:** " + dv.anovaError + "\n\n";
    }
    const TextTable comparisons = comparisonTable(dv.comparisons);
    if (!comparisons.rows.empty()) md += renderMarkdownTable(comparisons);
    for (const auto& figure : dv.figures) {
      const std::string name = figureStem + "_fig" + std::to_string(doc.figures.size() + 1) + ".svg";
      doc.figures.push_back({name, figure.svg});
      md += "![" + figure.caption + "](" + name + ")\n\n";
    }
  }
  for (const auto& s : report.sections) {
    md += "## " + s.heading + "\n\n";
    for (const auto& p : s.paragraphs) md += p + "\n\n";
    for (const auto& w : s.warnings) md += "> **" + w + "**\n\n";
    for (const auto& table : s.tables) md += renderMarkdownTable(table);
  }
  for (const auto& table : report.appendices) md += renderMarkdownTable(table);
  for (std::size_t k = 0; k < report.images.size(); ++k) {
    const std::string name = figureStem + "_image" + std::to_string(k + 1) + (report.images[k].mimeType == "image/png" ? ".png" : ".bin");
    doc.figures.push_back({name, report.images[k].bytes});
    md += "![" + report.images[k].caption + "](" + name + ")\n\n";
  }
  return doc;
}

}  // namespace tlab::analysis
