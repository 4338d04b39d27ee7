// tlab statcheck FILE|DIR... [--json|--csv] [--all-p-values] [statcheck's options]: find APA-style
// results (t, F, r, z, chi2, Q with p) in text, PDF and HTML files and flag those whose p does not
// follow from the statistic (rules in analysis/statcheck.hpp).
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include "analysis/document_text.hpp"
#include "analysis/number_format.hpp"
#include "analysis/result_json.hpp"
#include "analysis/statcheck.hpp"
#include "analysis/statcheck_csv.hpp"
#include "analysis/text_table.hpp"
#include "app/commands.hpp"

namespace tlab::app {

namespace {

namespace an = tlab::analysis;

struct StatcheckCommandOptions {
  std::vector<std::string> paths;
  an::StatcheckOptions check;
  bool pEqualAlphaNotSignificant = false;
  bool allowPZero = false;
  bool json = false;
  bool csv = false;
  bool allPValues = false;
};

std::string apaFactorText(const an::StatcheckReport& report) {
  const double f = an::roundedApaFactor(report);
  return std::isfinite(f) ? an::formatNumber(f, 2) : "NA";
}

void printText(const an::StatcheckReport& report) {
  an::TextTable t;
  t.caption = report.source + ": " + std::to_string(report.verdicts.size()) + " APA results, " +
              std::to_string(report.inconsistencies()) + " inconsistent, " + std::to_string(report.decisionErrors()) +
              " decision errors; " + std::to_string(report.pValues.size()) + " p-values (APA factor " +
              apaFactorText(report) + ", " + std::to_string(report.pValuesWithoutStatistic()) +
              " without a test statistic)";
  t.header = {"line", "result", "recomputed p", "verdict"};
  for (const auto& v : report.verdicts) {
    std::string verdict = v.consistent ? "consistent" : (v.decisionError ? "DECISION ERROR" : "INCONSISTENT");
    if (!v.note.empty() && !v.consistent) verdict += ": " + v.note;
    else if (!v.note.empty()) verdict += " (" + v.note + ")";
    const std::string p = an::formatP(v.pComputed) + (v.oneTailed ? " (one-tailed)" : "");
    t.rows.push_back({std::to_string(v.result.line), v.result.text, p, verdict});
  }
  if (t.rows.empty()) {
    std::cout << t.caption << "\n";
    return;
  }
  std::cout << an::renderPlainText(t);
}

void printPValues(const an::StatcheckReport& report) {
  an::TextTable t;
  t.caption = report.source + ": " + std::to_string(report.pValues.size()) + " p-values";
  t.header = {"line", "p"};
  for (const auto& p : report.pValues)
    t.rows.push_back({std::to_string(p.line), p.relation == an::PRelation::NotSignificant
                                                  ? "ns"
                                                  : "p " + std::string(an::pRelationSymbol(p.relation)) + " " + p.p.text});
  std::cout << (t.rows.empty() ? t.caption + "\n" : an::renderPlainText(t));
}

void run(StatcheckCommandOptions& o) {
  o.check.pEqualAlphaSignificant = !o.pEqualAlphaNotSignificant;
  o.check.pZeroError = !o.allowPZero;
  std::vector<an::StatcheckReport> reports;
  for (const auto& file : an::collectDocuments(o.paths)) reports.push_back(an::statcheckFile(file, o.check));
  if (o.csv) {
    if (o.allPValues) an::writePValuesCsv(std::cout, reports);
    else an::writeStatcheckCsv(std::cout, reports);
    return;
  }
  if (o.json) {
    nlohmann::json all = nlohmann::json::array();
    for (const auto& r : reports) all.push_back(an::toJson(r));
    std::cout << (all.size() == 1 ? all[0] : all).dump(2) << "\n";
    return;
  }
  std::size_t results = 0, errors = 0, decisions = 0;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    if (i > 0) std::cout << "\n";
    if (o.allPValues) printPValues(reports[i]);
    else printText(reports[i]);
    results += reports[i].verdicts.size();
    errors += reports[i].inconsistencies();
    decisions += reports[i].decisionErrors();
  }
  if (reports.size() > 1 && !o.allPValues)
    std::cout << "\nTotal: " << reports.size() << " files, " << results << " APA results, " << errors
              << " inconsistent, " << decisions << " decision errors\n";
}

}  // namespace

void addStatcheckCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "statcheck", "Check APA-style statistics (t, F, r, z, chi2, Q with p) in text, PDF and HTML files");
  const auto o = std::make_shared<StatcheckCommandOptions>();
  cmd->add_option("paths", o->paths, "Text (.txt or any), PDF (.pdf) or HTML (.htm, .html) files, or folders "
                                     "(searched recursively for .txt, .pdf, .htm, .html)")
      ->required();
  cmd->add_option("--alpha", o->check.alpha, "Significance level for decision errors")->capture_default_str();
  cmd->add_flag("--p-equal-alpha-not-significant", o->pEqualAlphaNotSignificant,
                "Count p = alpha as not significant (statcheck's pEqualAlphaSig = FALSE)");
  cmd->add_flag("--allow-p-zero", o->allowPZero, "Do not count p = .000 as an error (statcheck's pZeroError = FALSE)");
  cmd->add_flag("--one-tailed", o->check.oneTailedTests,
                "Treat every t, r and z test as one-tailed (statcheck's OneTailedTests)");
  cmd->add_flag("--one-tailed-text", o->check.oneTailedText,
                "Re-check errors one-tailed in texts that say one-sided/one-tailed/directional (statcheck's "
                "OneTailedTxt)");
  cmd->add_option("--stat", o->check.tests,
                  "Report only these test types: t, F, cor, chisq, Z, Q (statcheck's stat; default all)")
      ->delimiter(',');
  cmd->add_flag("--all-p-values", o->allPValues, "List every p-value instead of the results (statcheck's AllPValues)");
  auto* json = cmd->add_flag("--json", o->json, "Print JSON (statcheck's fields and tlab's)");
  cmd->add_flag("--csv", o->csv, "Print CSV for R (statcheck's columns first)")->excludes(json);
  cmd->callback([o] { run(*o); });
}

}  // namespace tlab::app
