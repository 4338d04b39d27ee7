#include "analysis/model_matrix.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

namespace {

// One variable of the formula on the complete rows.
struct Variable {
  bool numeric = false;
  std::vector<double> values;        // numeric
  std::vector<std::string> levels;   // factor
  std::vector<std::size_t> codes;    // factor: codes[row] indexes levels
};

bool isMissing(const std::string& cell) { return cell.find_first_not_of(" \t") == std::string::npos || cell == "NA"; }

// The rows with a value in every used column (R's na.omit).
std::vector<std::size_t> completeRows(const Table& table, const std::vector<std::string>& columns) {
  std::vector<std::size_t> index;
  for (const auto& c : columns) index.push_back(table.columnIndex(c));
  std::vector<std::size_t> rows;
  for (std::size_t r = 0; r < table.rowCount(); ++r)
    if (std::none_of(index.begin(), index.end(), [&](std::size_t c) { return isMissing(table.text(r, c)); })) rows.push_back(r);
  return rows;
}

Variable makeVariable(const Table& table, const std::string& name, const std::vector<std::size_t>& rows, const ModelVariables& spec) {
  const std::size_t c = table.columnIndex(name);
  Variable v;
  const auto given = spec.levels.find(name);
  v.numeric = !spec.factors.count(name) && given == spec.levels.end() && std::all_of(rows.begin(), rows.end(), [&](std::size_t r) {
    double x = 0.0;
    return parseDouble(table.text(r, c), x);
  });
  if (v.numeric) {
    for (const std::size_t r : rows) v.values.push_back(table.number(r, c));
    return v;
  }
  if (given != spec.levels.end()) v.levels = given->second;
  for (const std::size_t r : rows) {
    const std::string& cell = table.text(r, c);
    auto at = std::find(v.levels.begin(), v.levels.end(), cell);
    if (at == v.levels.end()) {
      if (given != spec.levels.end())
        throw AnalysisError(table.where(r) + ": column '" + name + "': '" + cell + "' is not one of the levels given");
      v.levels.push_back(cell);
      at = v.levels.end() - 1;
    }
    v.codes.push_back(static_cast<std::size_t>(at - v.levels.begin()));
  }
  // Levels that never occur would give all-zero columns: drop them as factor() of the data would.
  std::vector<bool> used(v.levels.size(), false);
  for (const auto code : v.codes) used[code] = true;
  std::vector<std::size_t> renumber(v.levels.size());
  std::vector<std::string> kept;
  for (std::size_t l = 0; l < v.levels.size(); ++l)
    if (used[l]) renumber[l] = kept.size(), kept.push_back(v.levels[l]);
  for (auto& code : v.codes) code = renumber[code];
  v.levels = std::move(kept);
  return v;
}

using Variables = std::map<std::string, Variable>;

// The columns of one variable within a term: contrasts (levels 2..k) or indicators (all levels).
struct Coding {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
};

Coding code(const std::string& name, const Variable& v, bool contrasts) {
  Coding c;
  if (v.numeric) {
    c.names.push_back(name);
    c.columns.push_back(v.values);
    return c;
  }
  for (std::size_t l = contrasts ? 1 : 0; l < v.levels.size(); ++l) {
    c.names.push_back(name + v.levels[l]);
    std::vector<double> column(v.codes.size());
    for (std::size_t r = 0; r < v.codes.size(); ++r) column[r] = v.codes[r] == l ? 1.0 : 0.0;
    c.columns.push_back(std::move(column));
  }
  return c;
}

bool contains(const LinearPredictor& p, const ModelTerm& term) {
  if (term.empty()) return p.intercept;
  return std::any_of(p.terms.begin(), p.terms.end(), [&](const ModelTerm& t) {
    return t.size() == term.size() && std::all_of(term.begin(), term.end(), [&](const std::string& v) {
             return std::find(t.begin(), t.end(), v) != t.end();
           });
  });
}

struct Columns {
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;
};

// R's model.matrix for a predictor: the intercept, then each term's product columns.
Columns modelColumns(const LinearPredictor& p, const Variables& vars, std::size_t n) {
  Columns out;
  if (p.intercept) out.names.push_back("(Intercept)"), out.values.emplace_back(n, 1.0);
  for (const auto& term : p.terms) {
    Columns product{{""}, {std::vector<double>(n, 1.0)}};
    for (const auto& name : term) {
      ModelTerm rest;
      for (const auto& other : term)
        if (other != name) rest.push_back(other);
      const Coding c = code(name, vars.at(name), contains(p, rest));
      Columns next;
      for (std::size_t j = 0; j < c.names.size(); ++j)       // later variables vary slowest
        for (std::size_t i = 0; i < product.names.size(); ++i) {
          next.names.push_back(product.names[i] + (product.names[i].empty() ? "" : ":") + c.names[j]);
          std::vector<double> column(n);
          for (std::size_t r = 0; r < n; ++r) column[r] = product.values[i][r] * c.columns[j][r];
          next.values.push_back(std::move(column));
        }
      product = std::move(next);
    }
    out.names.insert(out.names.end(), product.names.begin(), product.names.end());
    out.values.insert(out.values.end(), product.values.begin(), product.values.end());
  }
  return out;
}

// Keeps the columns not in the span of the columns kept before them (modified Gram-Schmidt with
// R's qr tolerance 1e-7 relative to the column's norm), like lme4's chkRank.drop.cols.
void fillFixedEffects(MixedModelMatrices& m, const Columns& columns, std::size_t n) {
  std::vector<Eigen::VectorXd> basis;
  std::vector<std::size_t> kept;
  for (std::size_t j = 0; j < columns.values.size(); ++j) {
    Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(columns.values[j].data(), static_cast<Eigen::Index>(n));
    const double norm = v.norm();
    for (const auto& b : basis) v -= b.dot(v) * b;
    if (norm == 0.0 || v.norm() <= 1e-7 * norm) {
      m.dropped.push_back(columns.names[j]);
      continue;
    }
    basis.push_back(v / v.norm());
    kept.push_back(j);
  }
  m.X.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(kept.size()));
  for (std::size_t k = 0; k < kept.size(); ++k) {
    m.xNames.push_back(columns.names[kept[k]]);
    for (std::size_t r = 0; r < n; ++r) m.X(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(k)) = columns.values[kept[k]][r];
  }
}

// The grouping factor of a random term: one column, or the observed combinations of several.
Variable groupingFactor(const Table& table, const std::vector<std::string>& grouping, const std::vector<std::size_t>& rows) {
  Variable g;
  std::map<std::string, std::size_t> index;
  for (const std::size_t r : rows) {
    std::string label;
    for (const auto& column : grouping) label += (label.empty() ? "" : ":") + table.text(r, table.columnIndex(column));
    const auto [at, inserted] = index.emplace(label, g.levels.size());
    if (inserted) g.levels.push_back(label);
    g.codes.push_back(at->second);
  }
  return g;
}

// Z and its blocks (Eqs. 6-7): the random-effects terms ordered by decreasing number of levels
// (mkReTrms: rev(order(nl))), each level's p_k columns side by side.
void fillRandomEffects(MixedModelMatrices& m, const Table& table, const ModelFormula& formula, const Variables& vars,
                       const std::vector<std::size_t>& rows) {
  const std::size_t n = rows.size();
  struct Term { RandomEffectsBlock block; Columns columns; Variable group; };
  std::vector<Term> terms;
  for (const auto& r : formula.random) {
    Term t{{}, modelColumns(r.expression, vars, n), groupingFactor(table, r.grouping, rows)};
    t.block.group = groupingLabel(r.grouping);
    t.block.columns = t.columns.names;
    t.block.levels = t.group.levels.size();
    // lme4's checks (mkReTrms, check.nobs.vs.nlev).
    if (t.block.levels < 2) throw AnalysisError("mixed model: grouping factor '" + t.block.group + "' must have > 1 sampled level");
    if (t.block.levels >= n)
      throw AnalysisError("mixed model: number of levels of grouping factor '" + t.block.group + "' (" + std::to_string(t.block.levels) +
                          ") must be < number of observations (" + std::to_string(n) + ")");
    terms.push_back(std::move(t));
  }
  std::vector<std::size_t> order(terms.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  bool increasing = false;
  for (std::size_t k = 1; k < terms.size(); ++k) increasing |= terms[k].block.levels > terms[k - 1].block.levels;
  if (increasing) {
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return terms[a].block.levels < terms[b].block.levels; });
    std::reverse(order.begin(), order.end());
  }
  std::vector<Eigen::Triplet<double>> triplets;
  std::size_t offset = 0, thetaOffset = 0;
  for (const std::size_t k : order) {
    Term& t = terms[k];
    t.block.offset = offset;
    t.block.thetaOffset = thetaOffset;
    const std::size_t pk = t.block.size();
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t j = 0; j < pk; ++j)
        if (t.columns.values[j][r] != 0.0)
          triplets.emplace_back(static_cast<int>(r), static_cast<int>(offset + t.group.codes[r] * pk + j), t.columns.values[j][r]);
    offset += pk * t.block.levels;
    thetaOffset += t.block.thetaCount();
    m.blocks.push_back(t.block);
  }
  m.Z.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(offset));
  m.Z.setFromTriplets(triplets.begin(), triplets.end());
}

}  // namespace

std::size_t MixedModelMatrices::thetaSize() const {
  std::size_t k = 0;
  for (const auto& b : blocks) k += b.thetaCount();
  return k;
}

MixedModelMatrices buildMixedModelMatrices(const Table& table, const ModelFormula& formula, const ModelVariables& spec) {
  std::vector<std::string> used = formula.variables();
  used.push_back(formula.response);
  for (const auto& r : formula.random) used.insert(used.end(), r.grouping.begin(), r.grouping.end());
  const std::vector<std::size_t> rows = completeRows(table, used);
  const std::size_t n = rows.size();
  if (n == 0) throw AnalysisError(table.source() + ": no row has a value in every column of the formula");
  MixedModelMatrices m;
  m.response = formula.logResponse ? "log(" + formula.response + ")" : formula.response;
  m.y.resize(static_cast<Eigen::Index>(n));
  const std::size_t yc = table.columnIndex(formula.response);
  for (std::size_t i = 0; i < n; ++i) {
    double v = table.number(rows[i], yc);
    if (formula.logResponse) {
      if (!(v > 0.0)) throw AnalysisError(table.where(rows[i]) + ": column '" + formula.response + "': log of " + table.text(rows[i], yc) + " is undefined");
      v = std::log(v);
    }
    m.y(static_cast<Eigen::Index>(i)) = v;
  }
  Variables vars;
  for (const auto& name : formula.variables()) vars.emplace(name, makeVariable(table, name, rows, spec));
  fillFixedEffects(m, modelColumns(formula.fixed, vars, n), n);

  fillRandomEffects(m, table, formula, vars, rows);
  return m;
}

}  // namespace tlab::analysis
