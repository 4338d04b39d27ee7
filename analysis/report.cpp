#include "analysis/report.hpp"

#include <algorithm>
#include <map>

#include "analysis/analysis_error.hpp"
#include "analysis/anova_design.hpp"
#include "analysis/r_moments.hpp"
#include "analysis/svg_plots.hpp"

namespace tlab::analysis {

namespace {

bool planHas(const AnalysisPlan& plan, PlannedTest test) {
  return std::find(plan.tests.begin(), plan.tests.end(), test) != plan.tests.end();
}

std::string joinLevels(const std::vector<std::string>& names, const std::vector<std::string>& levels,
                       std::size_t skip = SIZE_MAX) {
  std::string label;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    if (i == skip) continue;
    label += (label.empty() ? "" : ", ") + names[i] + "=" + levels[i];
  }
  return label;
}

std::vector<CellSummary> cellSummaries(const AnovaDesign& design, double confidence) {
  std::vector<std::string> names;
  for (const auto& f : design.between) names.push_back(f.name);
  for (const auto& f : design.within) names.push_back(f.name);
  // Between cells in level order (first factor slowest), each with the subjects in it.
  std::map<std::vector<std::size_t>, std::vector<std::size_t>> subjectsByGroup;
  for (std::size_t s = 0; s < design.subjects.size(); ++s) subjectsByGroup[design.betweenLevels[s]].push_back(s);
  std::vector<CellSummary> cells;
  for (const auto& [group, members] : subjectsByGroup) {
    for (std::size_t c = 0; c < design.cellCount(); ++c) {
      CellSummary cell;
      for (std::size_t f = 0; f < group.size(); ++f) cell.levels.push_back(design.between[f].levels[group[f]]);
      const auto withinLevels = withinCellLevels(design, c);
      for (std::size_t f = 0; f < withinLevels.size(); ++f)
        cell.levels.push_back(design.within[f].levels[withinLevels[f]]);
      cell.label = joinLevels(names, cell.levels);
      for (const std::size_t s : members) {
        cell.values.push_back(design.y(static_cast<Eigen::Index>(s), static_cast<Eigen::Index>(c)));
        cell.subjects.push_back(design.subjects[s]);
      }
      try {
        cell.stats = describe(cell.values, "cell " + cell.label, confidence);
      } catch (const AnalysisError& e) {
        cell.error = e.what();
      }
      cell.outliers = screenOutliers(cell.values);
      cells.push_back(std::move(cell));
    }
  }
  return cells;
}

// Each subject's mean over the within cells that have level `level` of within factor `factor`.
std::vector<double> marginalWithinMeans(const AnovaDesign& design, std::size_t factor, std::size_t level) {
  std::vector<double> means(design.subjects.size(), 0.0);
  for (std::size_t s = 0; s < design.subjects.size(); ++s) {
    std::vector<double> cells;
    for (std::size_t c = 0; c < design.cellCount(); ++c)
      if (withinCellLevels(design, c)[factor] == level)
        cells.push_back(design.y(static_cast<Eigen::Index>(s), static_cast<Eigen::Index>(c)));
    means[s] = rMean(cells);
  }
  return means;
}

// A subject's mean over all within cells.
double subjectMean(const AnovaDesign& design, std::size_t s) {
  const Eigen::RowVectorXd row = design.y.row(static_cast<Eigen::Index>(s));
  return rMean(std::span<const double>(row.data(), static_cast<std::size_t>(row.size())));
}

std::vector<Comparison> comparisons(const AnovaDesign& design, const AnalysisPlan& plan) {
  std::vector<Comparison> out;
  const bool tTests = planHas(plan, PlannedTest::TTests);
  const bool rankTests = planHas(plan, PlannedTest::RankTests);
  const std::size_t n = design.subjects.size();
  for (std::size_t f = 0; f < design.within.size(); ++f) {
    const auto& factor = design.within[f];
    Comparison c;
    c.factor = factor.name;
    std::vector<std::vector<double>> byLevel;
    for (std::size_t l = 0; l < factor.levels.size(); ++l) byLevel.push_back(marginalWithinMeans(design, f, l));
    try {
      if (factor.levels.size() == 2) {
        c.description = factor.name + ": " + factor.levels[0] + " vs " + factor.levels[1] + ", paired over " +
                        std::to_string(n) + " subjects";
        if (tTests) c.tTest = pairedTTest(byLevel[0], byLevel[1], Alternative::TwoSided, plan.confidence);
        if (rankTests) c.wilcoxon = wilcoxonSignedRankTest(byLevel[0], byLevel[1], 0.0, Alternative::TwoSided);
      } else if (rankTests) {
        c.description = factor.name + ": " + std::to_string(factor.levels.size()) + " levels, " +
                        std::to_string(n) + " subjects";
        Eigen::MatrixXd m(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(factor.levels.size()));
        for (std::size_t l = 0; l < byLevel.size(); ++l)
          for (std::size_t s = 0; s < n; ++s) m(static_cast<Eigen::Index>(s), static_cast<Eigen::Index>(l)) = byLevel[l][s];
        c.friedman = friedmanTest(m);
      } else {
        continue;
      }
    } catch (const AnalysisError& e) {
      c.error = e.what();
    }
    out.push_back(std::move(c));
  }
  for (std::size_t f = 0; f < design.between.size(); ++f) {
    const auto& factor = design.between[f];
    if (factor.levels.size() != 2 || !(tTests || rankTests)) continue;
    Comparison c;
    c.factor = factor.name;
    std::vector<double> groups[2];
    for (std::size_t s = 0; s < n; ++s)
      groups[design.betweenLevels[s][f]].push_back(subjectMean(design, s));
    c.description = factor.name + ": " + factor.levels[0] + " (n = " + std::to_string(groups[0].size()) + ") vs " +
                    factor.levels[1] + " (n = " + std::to_string(groups[1].size()) + ")";
    try {
      if (tTests) c.tTest = welchTTest(groups[0], groups[1], Alternative::TwoSided, plan.confidence);
      if (rankTests) c.mannWhitney = mannWhitneyTest(groups[0], groups[1], Alternative::TwoSided);
    } catch (const AnalysisError& e) {
      c.error = e.what();
    }
    out.push_back(std::move(c));
  }
  return out;
}

// A dependent variable on the scale [0, 1]: named a proportion by the plan, or every value 0 or 1.
bool isProportion(const Table& table, const AnalysisPlan& plan, const std::string& dv) {
  if (std::find(plan.proportions.begin(), plan.proportions.end(), dv) != plan.proportions.end()) return true;
  const std::vector<double> values = table.numericColumn(dv);
  return !values.empty() && std::all_of(values.begin(), values.end(), [](double v) { return v == 0.0 || v == 1.0; });
}

std::vector<Figure> figures(const std::string& dv, const AnovaDesign& design, const std::vector<CellSummary>& cells,
                            bool proportion) {
  std::vector<std::string> names;
  for (const auto& f : design.between) names.push_back(f.name);
  for (const auto& f : design.within) names.push_back(f.name);
  const std::size_t last = names.size() - 1;
  // Bars: the last factor's levels side by side, the other factors' combinations along x.
  BarChart bars;
  bars.title = "Mean " + dv + " per condition";
  bars.yLabel = dv;
  bars.errorBarMeaning = proportion ? "error bars: ±1 SD over subjects, clipped to [0, 1]" : "error bars: ±1 SD over subjects";
  if (proportion) {
    bars.yFloor = 0.0;
    bars.yCeiling = 1.0;
  }
  std::map<std::string, std::size_t> categoryIndex;
  std::map<std::string, std::size_t> seriesIndex;
  for (const auto& cell : cells) {
    const std::string category = names.size() > 1 ? joinLevels(names, cell.levels, last) : cell.levels[0];
    const std::string series = names.size() > 1 ? names[last] + "=" + cell.levels[last] : "";
    if (!categoryIndex.count(category)) {
      categoryIndex[category] = bars.categories.size();
      bars.categories.push_back(category);
    }
    if (!seriesIndex.count(series)) {
      seriesIndex[series] = bars.series.size();
      bars.series.push_back({series, {}, {}});
    }
  }
  for (auto& s : bars.series) {
    s.means.assign(bars.categories.size(), 0.0);
    s.errors.assign(bars.categories.size(), std::nan(""));
  }
  for (const auto& cell : cells) {
    const std::string category = names.size() > 1 ? joinLevels(names, cell.levels, last) : cell.levels[0];
    const std::string series = names.size() > 1 ? names[last] + "=" + cell.levels[last] : "";
    auto& s = bars.series[seriesIndex[series]];
    const std::size_t i = categoryIndex[category];
    if (cell.stats) {
      s.means[i] = cell.stats->mean;
      s.errors[i] = cell.stats->sd;
    } else if (!cell.values.empty()) {
      s.means[i] = cell.values.front();
    }
  }
  BoxPlot box;
  box.title = dv + " per condition";
  box.yLabel = dv;
  for (const auto& cell : cells) {
    std::string label;
    for (const auto& l : cell.levels) label += (label.empty() ? "" : " / ") + l;
    box.groups.push_back({label, cell.values});
  }
  const double width = std::max(640.0, 90.0 * static_cast<double>(cells.size()));
  return {{"Mean " + dv + " per condition (error bars: ±1 SD over subjects, as in Elmqvist et al. Figs. 9-10).",
           renderBarChartSvg(bars, width)},
          {"Box plots of " + dv + " per condition (box: quartiles; line: median; whiskers: 1.5 IQR; points: beyond).",
           renderBoxPlotSvg(box, width)}};
}

}  // namespace

Report makeReport(const Table& table, const AnalysisPlan& plan) {
  if (plan.dependentVariables.empty()) throw AnalysisError("the analysis plan names no dependent variable");
  if (plan.between.empty() && plan.within.empty())
    throw AnalysisError("the analysis plan names no factor (between or within)");
  Report report;
  report.title = plan.title;
  report.source = table.source();
  report.plan = plan;
  report.design.rows = table.rowCount();
  report.design.subject = plan.subject;
  for (const auto& dv : plan.dependentVariables) {
    const AnovaDesign design = makeAnovaDesign(table, dv, plan.between, plan.within, plan.subject);
    report.design.subjects = design.subjects.size();
    report.design.between = design.between;
    report.design.within = design.within;
    report.design.maxReplicates = std::max(report.design.maxReplicates, design.maxReplicates);
    DependentVariableReport r;
    r.dv = dv;
    r.cells = cellSummaries(design, plan.confidence);
    if (planHas(plan, PlannedTest::Anova)) {
      try {
        r.anova = anova(design, plan.ssType);
      } catch (const AnalysisError& e) {
        r.anovaError = e.what();
      }
    }
    r.comparisons = comparisons(design, plan);
    r.proportion = isProportion(table, plan, dv);
    r.figures = figures(dv, design, r.cells, r.proportion);
    report.dependentVariables.push_back(std::move(r));
  }
  if (report.design.maxReplicates > 1)
    report.notes.push_back("Several observations per subject and cell (up to " +
                           std::to_string(report.design.maxReplicates) +
                           ") were averaged first; all statistics are over subject means.");
  report.notes.push_back("ANOVA sums of squares: type " + std::string(sumOfSquaresTypeName(plan.ssType)) +
                         " (identical to the other type for balanced between-subject cells).");
  report.notes.push_back("Outlier screening: Tukey fences (beyond 1.5 IQR from the quartiles) and |z| > 3, per cell.");
  return report;
}

}  // namespace tlab::analysis
