// tlab analyze study.db [--json]: runs the analysis plan of the experiment stored in the database
// ([[analysis]] in its file) — ANOVA, t-tests and rank tests through analysis/, plus pairwise
// paired t-tests for within factors with more than two levels (p adjusted as the plan's
// correction says) and the mixed models of tests = ["mixed"] — and prints the results.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "analysis/mixed_model_report.hpp"
#include "analysis/number_format.hpp"
#include "analysis/result_json.hpp"
#include "analysis/text_table.hpp"
#include "app/analysis_text.hpp"
#include "app/commands.hpp"
#include "study/analyze/study_analysis.hpp"
#include "study/store/open_store.hpp"

namespace tlab::app {

namespace {

struct AnalyzeOptions {
  std::string db;
  bool json = false;
  std::string experiment;
  bool poolVersions = false;
};

nlohmann::json toJson(const study::StudyAnalysis& a) {
  nlohmann::json j = {{"title", a.spec.title}, {"tasks", a.spec.tasks}, {"within", a.spec.within}, {"between", a.spec.between},
                      {"alpha", a.spec.alpha}, {"subjects", a.report.design.subjects}, {"rows", a.report.design.rows}};
  j["dependent_variables"] = nlohmann::json::array();
  for (const auto& dv : a.report.dependentVariables) {
    nlohmann::json d = {{"dv", dv.dv}};
    if (dv.anova) d["anova"] = analysis::toJson(*dv.anova);
    if (!dv.anovaError.empty()) d["anova_error"] = dv.anovaError;
    d["comparisons"] = nlohmann::json::array();
    for (const auto& c : dv.comparisons) {
      nlohmann::json cj = {{"factor", c.factor}, {"description", c.description}};
      if (c.tTest) cj["t_test"] = analysis::toJson(*c.tTest);
      if (c.wilcoxon) cj["wilcoxon"] = analysis::toJson(*c.wilcoxon);
      if (c.mannWhitney) cj["mann_whitney"] = analysis::toJson(*c.mannWhitney);
      if (c.friedman) cj["friedman"] = analysis::toJson(*c.friedman);
      if (!c.error.empty()) cj["error"] = c.error;
      d["comparisons"].push_back(cj);
    }
    j["dependent_variables"].push_back(d);
  }
  j["pairwise"] = nlohmann::json::array();
  for (const auto& p : a.pairwise)
    j["pairwise"].push_back({{"dv", p.dv}, {"factor", p.factor}, {"first", p.first}, {"second", p.second}, {"t_test", analysis::toJson(p.test)},
                             {"p", p.test.p}, {"p_adjusted", p.pAdjusted}, {"correction", a.spec.correction}});
  j["mixed_models"] = nlohmann::json::array();
  for (const auto& m : a.mixed) {
    nlohmann::json mj = analysis::toJson(m.result);
    mj["dv"] = m.dv;
    j["mixed_models"].push_back(mj);
  }
  j["errors"] = a.errors;
  return j;
}

void run(const AnalyzeOptions& o) {
  const auto storeOwner = study::openStore(o.db, study::OpenMode::Read);
  study::Store& store = *storeOwner;
  const study::StoredExperiment stored = study::storedExperiment(store, o.experiment, o.poolVersions);
  if (stored.experiment.analyses.empty()) throw std::runtime_error(stored.experiment.path + ": the experiment plans no [[analysis]]");
  const auto analyses = study::analyzeStudy(store, stored);
  if (o.json) {
    nlohmann::json j = {{"experiment", stored.experiment.id}, {"database", o.db}, {"analyses", nlohmann::json::array()}};
    for (const auto& v : stored.versions)
      j["versions"].push_back({{"version", v.version.version}, {"sha256", v.version.sha256}, {"design", v.design}, {"sessions", v.sessions}});
    for (const auto& a : analyses) j["analyses"].push_back(toJson(a));
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("experiment '%s': data from %s\n\n", stored.experiment.id.c_str(), stored.describeVersions().c_str());
  for (const auto& a : analyses) std::fputs(analysisText(a).c_str(), stdout);
}

}  // namespace

void addAnalyzeCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("analyze", "Run the experiment's analysis plan on a study database");
  auto o = std::make_shared<AnalyzeOptions>();
  cmd->add_option("db", o->db, "study database")->required();
  cmd->add_flag("--json", o->json, "print JSON");
  cmd->add_option("--experiment", o->experiment, "experiment id (when the database holds several)");
  cmd->add_flag("--pool-versions", o->poolVersions, "analyse data of experiment versions whose designs differ together");
  cmd->callback([o] { run(*o); });
}

}  // namespace tlab::app
