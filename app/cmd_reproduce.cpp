// tlab reproduce carnecky|elmqvist [--json]: recompute the seeds' published statistics from the
// numbers they print and say what the printed numbers are consistent with.
// tlab reproduce --table FILE.csv [--json]: the same question as `carnecky` (Welch, Student or
// paired?) for any paper's two-group comparisons (format in analysis/reproduce_table.hpp).
#include <cmath>
#include <iostream>
#include <memory>

#include "analysis/number_format.hpp"
#include "analysis/reproduce_carnecky.hpp"
#include "analysis/reproduce_elmqvist.hpp"
#include "analysis/reproduce_table.hpp"
#include "analysis/result_json.hpp"
#include "analysis/text_table.hpp"
#include "app/commands.hpp"

namespace tlab::app {

namespace {

namespace an = tlab::analysis;

std::string range(const an::Interval& i, int digits = 4) {
  return "[" + an::formatNumber(i.lo, digits) + ", " + an::formatNumber(i.hi, digits) + "]";
}

std::string yesNo(bool b) { return b ? "yes" : "NO"; }

void printFindings(const std::vector<std::string>& findings) {
  std::cout << "\nFindings:\n";
  for (const auto& f : findings) std::cout << "  - " << f << "\n";
}

void printCarnecky(const an::CarneckyReproduction& r) {
  std::cout << "Carnecky et al. 2013, Table 1 (n = 36 per method; one-sided p = P(T < -|t|))\n\n";
  for (const auto& row : r.rows) {
    const auto& c = row.published;
    an::TextTable t;
    t.caption = c.first + " (" + c.mean1.text + ", var " + c.variance1.text + ") vs " + c.second + " (" + c.mean2.text +
                ", var " + c.variance2.text + "); published: df " + c.df.text + ", t " + c.t.text + ", p " +
                c.pOneSided.text + "; text p = " + c.pInText.text;
    t.header = {"test", "t", "df", "p one-sided", "|t| range", "df range", "p range", "df ok", "t ok", "p ok", "consistent"};
    for (const auto& h : row.checks) {
      if (h.kind == an::TTestKind::Paired) {
        t.rows.push_back({"paired", "depends on r", an::formatNumber(h.df), "-", "any", range(h.dfRange), "-",
                          yesNo(h.dfConsistent), "-", "-", yesNo(h.consistent())});
        continue;
      }
      t.rows.push_back({std::string(an::tTestKindName(h.kind)), an::formatNumber(h.t), an::formatNumber(h.df),
                        an::formatP(h.pOneSided), range(h.absTRange), range(h.dfRange), range(h.pRange),
                        yesNo(h.dfConsistent), yesNo(h.tConsistent), yesNo(h.pConsistent), yesNo(h.consistent())});
    }
    std::cout << an::renderPlainText(t);
    const auto& paired = row.checks.back();
    std::cout << "  paired reading: the printed t needs r = " << an::formatNumber(paired.impliedCorrelation, 3)
              << " (range " << range(paired.impliedCorrelationRange, 3) << ") between the two methods\n"
              << "  two-sided Welch p = " << an::formatP(row.pTwoSidedWelch) << "\n\n";
  }
  std::cout << "Conclusion: the published numbers are consistent with "
            << (r.rows.front().checks[0].consistent() ? "Welch's unequal-variance t-test" : "no tested hypothesis")
            << ", not with the paired t-test of the caption.\n";
  printFindings(r.findings);
}

void printElmqvist(const an::ElmqvistReproduction& r) {
  an::TextTable t;
  t.caption = "Elmqvist et al., Sec. VII: reported F(1,15) tests (n = 16 participants)";
  t.header = {"measure", "inactive", "active", "F", "p reported", "p recomputed", "p range", "p ok", "implied r",
              "r range"};
  for (const auto& c : r.fTests) {
    const auto& p = c.published;
    t.rows.push_back({p.measure, p.meanInactive.text + " (" + p.sdInactive.text + ")",
                      p.meanActive.text + " (" + p.sdActive.text + ")", p.F.text,
                      std::string(an::pRelationSymbol(p.pRelation)) + " " + p.p.text, an::formatP(c.pComputed),
                      range(c.pRange, 3), yesNo(c.pConsistent), an::formatNumber(c.impliedCorrelation, 3),
                      range(c.impliedCorrelationRange, 3)});
  }
  std::cout << an::renderPlainText(t);
  std::cout << "\nDesign count: 2 x 2 x 16 x 3 = " << r.designCount << "; reported tasks: " << r.reportedTaskCount
            << " (= " << r.designCount << " x " << r.tasksPerScenario << " tasks per scenario)\n";
  printFindings(r.findings);
}

std::string printedOrDash(const std::optional<an::ReportedValue>& v) { return v ? v->text : "-"; }

void printTable(const std::vector<an::TableComparison>& rows) {
  for (const auto& row : rows) {
    const an::PrintedTTest& p = row.printed;
    an::TextTable t;
    t.caption = row.where + ": " + row.first + " (" + p.mean1.text + ", var " + an::formatNumber(p.variance1) +
                ", n " + an::formatNumber(p.n1) + ") vs " + row.second + " (" + p.mean2.text + ", var " +
                an::formatNumber(p.variance2) + ", n " + an::formatNumber(p.n2) + "); printed: df " +
                printedOrDash(p.df) + ", t " + printedOrDash(p.t) + ", p " + printedOrDash(p.p) +
                (p.pTails == 1 ? " (one-sided)" : " (two-sided)");
    t.header = {"test", "t", "df", "|t| range", "df range", "p range", "df ok", "t ok", "p ok", "consistent"};
    std::string consistentWith;
    for (const auto& h : row.checks) {
      const bool paired = h.kind == an::TTestKind::Paired;
      t.rows.push_back({std::string(an::tTestKindName(h.kind)), paired ? "depends on r" : an::formatNumber(h.t),
                        an::formatNumber(h.df), paired ? "any" : range(h.absTRange), range(h.dfRange),
                        paired ? "-" : range(h.pRange), yesNo(h.dfConsistent), paired ? "-" : yesNo(h.tConsistent),
                        paired ? "-" : yesNo(h.pConsistent), yesNo(h.consistent())});
      if (h.consistent()) consistentWith += (consistentWith.empty() ? "" : ", ") + std::string(an::tTestKindName(h.kind));
    }
    std::cout << an::renderPlainText(t);
    if (row.checks.size() == 3 && std::isfinite(row.checks[2].impliedCorrelation))
      std::cout << "  paired reading: the printed t needs r = " << an::formatNumber(row.checks[2].impliedCorrelation, 3)
                << " between the two conditions\n";
    std::cout << "  consistent with: " << (consistentWith.empty() ? "no tested hypothesis" : consistentWith) << "\n\n";
  }
}

}  // namespace

void addReproduceCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("reproduce", "Recompute published statistics: the seed papers, or any table (--table)");
  cmd->require_subcommand(0, 1);
  const auto json = std::make_shared<bool>(false);
  const auto table = std::make_shared<std::string>();
  cmd->add_option("--table", *table,
                  "CSV of printed two-group comparisons (mean1,var1|sd1,n1,mean2,var2|sd2,n2[,df,t,p,p_tails]): "
                  "which t-test (Welch, Student, paired) reproduces them")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--json", *json, "Print JSON");
  cmd->callback([cmd, json, table] {
    if (table->empty()) {
      if (cmd->get_subcommands().empty()) throw CLI::RequiredError("reproduce needs carnecky, elmqvist or --table FILE.csv");
      return;
    }
    if (!cmd->get_subcommands().empty()) throw CLI::ValidationError("--table", "give either --table or a paper, not both");
    const std::vector<an::TableComparison> rows = an::reproduceTable(*table);
    if (*json) std::cout << an::toJson(rows).dump(2) << "\n";
    else printTable(rows);
  });
  auto* carnecky = cmd->add_subcommand("carnecky", "Carnecky et al. 2013, Table 1: Welch, Student or paired?");
  carnecky->add_flag("--json", *json, "Print JSON");
  carnecky->callback([json] {
    const an::CarneckyReproduction r = an::reproduceCarnecky();
    if (*json) std::cout << an::toJson(r).dump(2) << "\n";
    else printCarnecky(r);
  });
  auto* elmqvist = cmd->add_subcommand("elmqvist", "Elmqvist et al.: every F(1,15), the design count, implied r");
  elmqvist->add_flag("--json", *json, "Print JSON");
  elmqvist->callback([json] {
    const an::ElmqvistReproduction r = an::reproduceElmqvist();
    if (*json) std::cout << an::toJson(r).dump(2) << "\n";
    else printElmqvist(r);
  });
}

}  // namespace tlab::app
