// tlab stats ttest|anova|friedman|wilcoxon|mannwhitney FILE.csv ...: statistical tests on a
// long-format CSV file. Prints a readable table, or JSON with --json (full double precision).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "analysis/anova.hpp"
#include "analysis/anova_design.hpp"
#include "analysis/analysis_error.hpp"
#include "analysis/bayes_factor.hpp"
#include "analysis/number_format.hpp"
#include "analysis/csv_reader.hpp"
#include "analysis/mixed_model_report.hpp"
#include "analysis/report_tables.hpp"
#include "analysis/result_json.hpp"
#include "analysis/row_filter.hpp"
#include "analysis/table_tests.hpp"
#include "app/commands.hpp"

namespace tlab::app {

namespace {

namespace an = tlab::analysis;

struct StatsOptions {
  std::string file;
  std::string dv;
  std::vector<std::string> between;
  std::vector<std::string> within;
  std::string subject;
  bool student = false;
  bool welch = false;
  std::string alternative = "two-sided";
  double mu = 0.0;
  double confidence = 0.95;
  std::string ssType = "2";
  bool json = false;
  std::vector<std::string> where;  // COLUMN=V1,V2 (every filter must hold)
  bool bayes = false;
  double rscale = an::kMediumCauchyScale;
  std::string adjust = "holm";
  std::vector<std::string> levels;
  bool noPoolSd = false;
  std::string formula;
  std::string family = "gaussian";
  bool ml = false;
  std::vector<std::string> factors;
  std::vector<std::string> levelSpecs;  // "COLUMN=a,b,c"
};

// --where, on every stats command.
void addWhereOption(CLI::App* cmd, StatsOptions& o) {
  cmd->add_option("--where", o.where,
                  "Keep only the rows whose COLUMN is one of the values: COLUMN=V1,V2 (repeatable; all must hold)")
      ->allow_extra_args(false);
}

void addCommonOptions(CLI::App* cmd, StatsOptions& o) {
  cmd->add_option("file", o.file, "Long-format CSV file (header row)")->required();
  cmd->add_option("--dv", o.dv, "Column of the dependent variable")->required();
  cmd->add_flag("--json", o.json, "Print JSON instead of a table");
  addWhereOption(cmd, o);
}

// The rows a test reads: the CSV file, filtered by --where, without the rows whose dependent
// variable is missing (an empty cell or NA, as R's na.omit drops them). What was dropped is said
// on a note line (stdout) or in the JSON's "input_rows" object.
struct StatsInput {
  an::Table table;
  nlohmann::json rows;
};

StatsInput readInput(const StatsOptions& o) {
  const an::Table all = an::readCsvFile(o.file);
  std::vector<an::RowFilter> filters;
  for (const auto& w : o.where) filters.push_back(an::parseRowFilter(w));
  const an::Table kept = an::rowsMatching(all, filters);
  if (kept.rowCount() == 0 && !filters.empty())
    throw an::AnalysisError(o.file + ": no row passes --where " + o.where.front() + (o.where.size() > 1 ? " ..." : ""));
  // The mixed model has no --dv: it drops the rows missing any variable of its formula itself.
  an::WithoutMissing complete = o.dv.empty() ? an::WithoutMissing{kept, 0} : an::dropMissing(kept, o.dv);
  nlohmann::json rows = {{"read", all.rowCount()}, {"kept_by_where", kept.rowCount()},
                         {"dropped_missing_dv", complete.dropped}, {"used", complete.table.rowCount()}};
  if (!o.json && filters.size() > 0)
    std::cout << "rows: " << kept.rowCount() << " of " << all.rowCount() << " kept by --where\n";
  if (!o.json && complete.dropped > 0)
    std::cout << "note: " << complete.dropped << " row" << (complete.dropped == 1 ? "" : "s") << " with a missing '" << o.dv
              << "' (empty or NA) dropped, as R's na.omit would\n";
  return {std::move(complete.table), std::move(rows)};
}

void printJson(nlohmann::json j, const StatsInput& input) {
  j["input_rows"] = input.rows;
  std::cout << j.dump(2) << "\n";
}

void print(const an::TextTable& table) { std::cout << an::renderPlainText(table); }

std::string single(const std::vector<std::string>& columns, const char* option) {
  if (columns.size() > 1) throw an::AnalysisError(std::string(option) + " takes one column for this test");
  return columns.empty() ? std::string() : columns.front();
}

void runTTest(const StatsOptions& o) {
  an::TTestRequest request;
  request.dv = o.dv;
  request.between = single(o.between, "--between");
  request.within = single(o.within, "--within");
  request.subject = o.subject;
  request.student = o.student;
  request.alternative = an::parseAlternative(o.alternative);
  request.mu = o.mu;
  request.confidence = o.confidence;
  if (!request.within.empty() && request.subject.empty())
    throw an::AnalysisError("--within needs --subject (the column naming the participant)");
  if ((o.student || o.welch) && request.between.empty())
    throw an::AnalysisError("--student/--welch apply to the two-sample test (--between) only");
  const StatsInput input = readInput(o);
  const an::TTestResult r = an::tTestOnTable(input.table, request);
  const double bf10 = o.bayes ? an::jzsBayesFactor10(r, o.rscale) : 0.0;
  if (o.json) {
    nlohmann::json j = an::toJson(r);
    if (o.bayes) j["bf10"] = bf10, j["rscale"] = o.rscale;
    return printJson(j, input);
  }
  print(an::tTestTable(r));
  if (o.bayes)
    std::cout << "\nJZS Bayes factor (Rouder et al. 2009, Cauchy prior scale " << an::formatNumber(o.rscale, 6)
              << "): BF10 = " << an::formatNumber(bf10, 6) << ", BF01 = " << an::formatNumber(1.0 / bf10, 6) << "\n";
}

void runPairwise(const StatsOptions& o) {
  an::PairwiseRequest request;
  request.dv = o.dv;
  request.within = single(o.within, "--within");
  request.between = single(o.between, "--between");
  request.subject = o.subject;
  request.levels = o.levels;
  request.adjust = an::parsePAdjustMethod(o.adjust);
  request.poolSd = !o.noPoolSd;
  const StatsInput input = readInput(o);
  const an::PairwiseResult r = an::pairwiseTTestsOnTable(input.table, request);
  if (o.json) return printJson(an::toJson(r), input);
  print(an::pairwiseTable(r));
}

void runAnova(const StatsOptions& o) {
  if (!o.within.empty() && o.subject.empty())
    throw an::AnalysisError("--within needs --subject (the column naming the participant)");
  const StatsInput input = readInput(o);
  const an::AnovaDesign design = an::makeAnovaDesign(input.table, o.dv, o.between, o.within, o.subject);
  const an::AnovaResult r = an::anova(design, an::parseSumOfSquaresType(o.ssType));
  if (o.json) return printJson(an::toJson(r), input);
  print(an::anovaTable(r));
  const an::TextTable sphericity = an::sphericityTable(r);
  if (!sphericity.rows.empty()) {
    std::cout << "\n";
    print(sphericity);
  }
  if (r.maxReplicates > 1)
    std::cout << "\nnote: up to " << r.maxReplicates << " observations per subject and cell were averaged.\n";
}

void runFriedman(const StatsOptions& o) {
  const StatsInput input = readInput(o);
  const an::FriedmanResult r =
      an::friedmanOnTable(input.table, o.dv, single(o.within, "--within"), o.subject);
  if (o.json) return printJson(an::toJson(r), input);
  print(an::friedmanTable(r));
}

void runWilcoxon(const StatsOptions& o) {
  const StatsInput input = readInput(o);
  const an::WilcoxonSignedRankResult r = an::wilcoxonOnTable(
      input.table, o.dv, single(o.within, "--within"), o.subject, an::parseAlternative(o.alternative));
  if (o.json) return printJson(an::toJson(r), input);
  print(an::wilcoxonTable(r));
}

void runMannWhitney(const StatsOptions& o) {
  const StatsInput input = readInput(o);
  const an::MannWhitneyResult r = an::mannWhitneyOnTable(input.table, o.dv, single(o.between, "--between"),
                                                         an::parseAlternative(o.alternative));
  if (o.json) return printJson(an::toJson(r), input);
  print(an::mannWhitneyTable(r));
}

// --levels COLUMN=a,b,c (repeatable): the level order of a factor, the first being the reference.
an::ModelVariables modelVariables(const StatsOptions& o) {
  an::ModelVariables v;
  v.factors.insert(o.factors.begin(), o.factors.end());
  for (const auto& spec : o.levelSpecs) {
    const auto eq = spec.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
      throw an::AnalysisError("--levels '" + spec + "': write COLUMN=LEVEL1,LEVEL2,...");
    auto& levels = v.levels[spec.substr(0, eq)];
    for (std::size_t start = eq + 1;;) {
      const auto comma = spec.find(',', start);
      levels.push_back(spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return v;
}

void runMixed(const StatsOptions& o) {
  an::MixedModelRequest request;
  request.formula = o.formula;
  request.family = an::parseMixedFamily(o.family);
  request.reml = !o.ml;
  if (o.ml && request.family == an::MixedFamily::Binomial) throw an::AnalysisError("--ml applies to the gaussian family only");
  request.variables = modelVariables(o);
  const StatsInput input = readInput(o);
  const an::MixedModelResult r = an::fitMixedModel(input.table, request);
  for (const auto& w : r.warnings) std::cerr << "warning: " << w << "\n";
  if (o.json) return printJson(an::toJson(r), input);
  std::cout << r.description() << "\n" << an::fitSummaryLine(r) << "\n\n";
  print(an::fixedEffectsTable(r));
  std::cout << "\n";
  print(an::randomEffectsTable(r));
}

}  // namespace

void addStatsCommand(CLI::App& app) {
  auto* stats = app.add_subcommand("stats", "Statistical tests on a long-format CSV file");
  stats->require_subcommand(1);
  const auto options = std::make_shared<StatsOptions>();
  StatsOptions& o = *options;

  auto* ttest = stats->add_subcommand("ttest", "t-test: two-sample (--between), paired (--within --subject) or one-sample");
  addCommonOptions(ttest, o);
  ttest->add_option("--between", o.between, "Two-level column splitting the rows into two groups");
  ttest->add_option("--within", o.within, "Two-level within-subject column (paired test)");
  ttest->add_option("--subject", o.subject, "Subject column (with --within)");
  auto* student = ttest->add_flag("--student", o.student, "Student's pooled-variance test");
  auto* welch = ttest->add_flag("--welch", o.welch, "Welch's unequal-variance test (default)");
  student->excludes(welch);
  ttest->add_option("--alternative", o.alternative, "two-sided, less or greater")->capture_default_str();
  ttest->add_option("--mu", o.mu, "Hypothesized mean (one-sample test)")->capture_default_str();
  ttest->add_option("--conf-level", o.confidence, "Confidence level of the interval")->capture_default_str();
  ttest->add_flag("--bayes", o.bayes, "Also the JZS Bayes factor BF10 (Rouder et al. 2009; two-sided)");
  ttest->add_option("--rscale", o.rscale, "Scale of the Cauchy prior on the effect size (sqrt(2)/2: 'medium')")
      ->capture_default_str();
  ttest->callback([options] { runTTest(*options); });

  auto* pairwise = stats->add_subcommand("pairwise", "Pairwise t-tests of every two levels, p adjusted (R's pairwise.t.test)");
  addCommonOptions(pairwise, o);
  pairwise->add_option("--within", o.within, "Within-subject factor (paired tests; needs --subject)");
  pairwise->add_option("--between", o.between, "Between-subject factor (independent groups)");
  pairwise->add_option("--subject", o.subject, "Subject column: replicates are averaged per subject and level");
  pairwise->add_option("--adjust", o.adjust, "p adjustment: holm, bonferroni, hochberg, BH, BY or none")->capture_default_str();
  pairwise->add_option("--levels", o.levels, "Levels to compare, in this order (comma-separated)")->delimiter(',');
  pairwise->add_flag("--no-pool-sd", o.noPoolSd, "Between: Welch's test per pair instead of the pooled SD of all groups");
  pairwise->callback([options] { runPairwise(*options); });

  auto* mixed = stats->add_subcommand("mixed", "Linear or logistic mixed model (lme4 formula; REML/ML or Laplace)");
  mixed->add_option("file", o.file, "Long-format CSV file (header row)")->required();
  mixed->add_option("--formula", o.formula, "lme4 formula, e.g. \"log(rt) ~ method + (1|participant) + (1|stimulus)\"")->required();
  mixed->add_option("--family", o.family, "gaussian (lmer) or binomial (glmer, logit link)")->capture_default_str();
  mixed->add_flag("--ml", o.ml, "Maximum likelihood instead of REML (gaussian)");
  mixed->add_option("--factor", o.factors, "Treat this numeric column as a factor (repeatable)")->allow_extra_args(false);
  mixed->add_option("--levels", o.levelSpecs, "COLUMN=L1,L2,...: level order, L1 the reference (repeatable)")->allow_extra_args(false);
  mixed->add_flag("--json", o.json, "Print JSON instead of tables");
  addWhereOption(mixed, o);
  mixed->callback([options] { runMixed(*options); });

  auto* anovaCmd = stats->add_subcommand("anova", "ANOVA: between, repeated-measures or mixed");
  addCommonOptions(anovaCmd, o);
  anovaCmd->add_option("--between", o.between, "Between-subject factor column(s), comma-separated")->delimiter(',');
  anovaCmd->add_option("--within", o.within, "Within-subject factor column(s), comma-separated")->delimiter(',');
  anovaCmd->add_option("--subject", o.subject, "Subject column (required with --within)");
  anovaCmd->add_option("--ss-type", o.ssType, "Sums of squares for unbalanced data: 2 or 3")->capture_default_str();
  anovaCmd->callback([options] { runAnova(*options); });

  auto* friedman = stats->add_subcommand("friedman", "Friedman rank sum test (chi-squared form)");
  addCommonOptions(friedman, o);
  friedman->add_option("--within", o.within, "Within-subject condition column")->required();
  friedman->add_option("--subject", o.subject, "Subject column")->required();
  friedman->callback([options] { runFriedman(*options); });

  auto* wilcoxon = stats->add_subcommand("wilcoxon", "Wilcoxon signed-rank test (paired)");
  addCommonOptions(wilcoxon, o);
  wilcoxon->add_option("--within", o.within, "Two-level within-subject column")->required();
  wilcoxon->add_option("--subject", o.subject, "Subject column")->required();
  wilcoxon->add_option("--alternative", o.alternative, "two-sided, less or greater")->capture_default_str();
  wilcoxon->callback([options] { runWilcoxon(*options); });

  auto* mannWhitney = stats->add_subcommand("mannwhitney", "Wilcoxon-Mann-Whitney rank sum test");
  addCommonOptions(mannWhitney, o);
  mannWhitney->add_option("--between", o.between, "Two-level column splitting the rows into two groups")->required();
  mannWhitney->add_option("--alternative", o.alternative, "two-sided, less or greater")->capture_default_str();
  mannWhitney->callback([options] { runMannWhitney(*options); });
}

}  // namespace tlab::app
