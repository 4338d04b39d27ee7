// tlab statcheck FILE.txt [--json]: find APA-style results (t, F, chi2 with p) in a text and flag
// those whose p does not follow from the statistic (rules in analysis/statcheck.hpp).
#include <iostream>
#include <memory>
#include <string>

#include "analysis/number_format.hpp"
#include "analysis/result_json.hpp"
#include "analysis/statcheck.hpp"
#include "analysis/text_table.hpp"
#include "app/commands.hpp"

namespace tlab::app {

namespace {

namespace an = tlab::analysis;

struct StatcheckOptions {
  std::vector<std::string> files;
  double alpha = 0.05;
  bool json = false;
};

void printText(const an::StatcheckReport& report) {
  an::TextTable t;
  t.caption = report.source + ": " + std::to_string(report.verdicts.size()) + " APA results, " +
              std::to_string(report.inconsistencies()) + " inconsistent, " + std::to_string(report.decisionErrors()) +
              " decision errors; " + std::to_string(report.pValuesWithoutStatistic) +
              " p-values without a test statistic (not checkable)";
  t.header = {"line", "result", "recomputed p", "verdict"};
  for (const auto& v : report.verdicts) {
    std::string verdict = v.consistent ? "consistent" : (v.decisionError ? "DECISION ERROR" : "INCONSISTENT");
    if (!v.note.empty() && !v.consistent) verdict += ": " + v.note;
    else if (!v.note.empty()) verdict += " (" + v.note + ")";
    t.rows.push_back({std::to_string(v.result.line), v.result.text, an::formatP(v.pComputed), verdict});
  }
  if (t.rows.empty()) {
    std::cout << t.caption << "\n";
    return;
  }
  std::cout << an::renderPlainText(t);
}

}  // namespace

void addStatcheckCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("statcheck", "Check APA-style statistics (t, F, chi2 with p) in text files");
  const auto options = std::make_shared<StatcheckOptions>();
  cmd->add_option("files", options->files, "Text file(s) to scan")->required();
  cmd->add_option("--alpha", options->alpha, "Significance level for decision errors")->capture_default_str();
  cmd->add_flag("--json", options->json, "Print JSON");
  cmd->callback([options] {
    nlohmann::json all = nlohmann::json::array();
    bool first = true;
    for (const auto& file : options->files) {
      const an::StatcheckReport report = an::statcheckFile(file, options->alpha);
      if (options->json) {
        all.push_back(an::toJson(report));
        continue;
      }
      if (!first) std::cout << "\n";
      first = false;
      printText(report);
    }
    if (options->json) std::cout << (all.size() == 1 ? all[0] : all).dump(2) << "\n";
  });
}

}  // namespace tlab::app
