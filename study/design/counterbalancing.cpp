#include "study/design/counterbalancing.hpp"

#include "study/design/graeco_latin_square.hpp"
#include "study/design/order_permutations.hpp"
#include "study/design/williams_design.hpp"

namespace tlab::study {

namespace {

// Every combination of the factors' levels, first factor slowest.
std::vector<std::vector<int>> combinations(const std::vector<const Factor*>& factors) {
  std::vector<std::vector<int>> out = {{}};
  for (const Factor* f : factors) {
    std::vector<std::vector<int>> next;
    for (const auto& prefix : out)
      for (int level = 0; level < int(f->levels.size()); ++level) {
        auto c = prefix;
        c.push_back(level);
        next.push_back(std::move(c));
      }
    out = std::move(next);
  }
  return out;
}

// Rows of Graeco-Latin positions as indices into the within combinations (first factor slowest).
OrderTable graecoLatinRows(const std::vector<const Factor*>& within) {
  if (within.size() != 2 || within[0]->levels.size() != within[1]->levels.size())
    throw DesignError("graeco-latin needs exactly two within factors with the same number of levels");
  const int n = int(within[0]->levels.size());
  const GraecoLatinSquare square = graecoLatinSquare(n);
  OrderTable rows;
  for (int r = 0; r < n; ++r) {
    std::vector<int> row;
    for (int c = 0; c < n; ++c) row.push_back(square.latin[r][c] * n + square.greek[r][c]);
    rows.push_back(row);
  }
  return rows;
}

OrderTable orderRows(const Experiment& e, const std::vector<const Factor*>& within, int conditions) {
  switch (e.counterbalancing) {
    case Counterbalancing::Fixed: return {cyclicLatinSquare(conditions).front()};
    case Counterbalancing::LatinSquare: return cyclicLatinSquare(conditions);
    case Counterbalancing::Williams: return williamsDesign(conditions);
    case Counterbalancing::GraecoLatin: return graecoLatinRows(within);
    case Counterbalancing::Permutation: return allPermutations(conditions);
    case Counterbalancing::Random: {
      OrderTable rows;
      for (int p = 0; p < e.participants; ++p) rows.push_back(seededRandomOrder(conditions, mixSeed(e.seed, std::uint64_t(p))));
      return rows;
    }
  }
  throw DesignError("unknown counterbalancing");
}

}  // namespace

Design::Design(const Experiment& experiment, OrderTable rows, std::vector<std::vector<int>> withinConditions,
               std::vector<std::vector<int>> betweenCells)
    : experiment_(&experiment), rows_(std::move(rows)), withinConditions_(std::move(withinConditions)),
      betweenCells_(std::move(betweenCells)) {}

SlotDesign Design::slot(int slot) const {
  SlotDesign d;
  d.slot = slot;
  const int cells = int(betweenCells_.size());
  d.betweenCell = slot % cells;
  d.row = (slot / cells) % int(rows_.size());
  for (const int conditionIndex : rows_[std::size_t(d.row)]) {
    Condition c;
    std::size_t w = 0, b = 0;
    for (const auto& f : experiment_->factors)
      c.levels.push_back(f.kind == FactorKind::Within ? withinConditions_[std::size_t(conditionIndex)][w++]
                                                      : betweenCells_[std::size_t(d.betweenCell)][b++]);
    d.blocks.push_back(std::move(c));
  }
  return d;
}

std::map<std::string, std::string> Design::levelNames(const Condition& condition) const {
  std::map<std::string, std::string> out;
  for (std::size_t i = 0; i < experiment_->factors.size(); ++i)
    out[experiment_->factors[i].name] = experiment_->factors[i].levels[std::size_t(condition.levels[i])].name;
  return out;
}

std::string Design::describe(const Condition& condition) const {
  std::string text;
  for (std::size_t i = 0; i < experiment_->factors.size(); ++i)
    text += (i ? ", " : "") + experiment_->factors[i].name + "=" + experiment_->factors[i].levels[std::size_t(condition.levels[i])].name;
  return text.empty() ? "(no factors)" : text;
}

Design makeDesign(const Experiment& experiment) {
  const auto within = experiment.withinFactors();
  auto withinConditions = combinations(within);
  auto betweenCells = combinations(experiment.betweenFactors());
  OrderTable rows = orderRows(experiment, within, int(withinConditions.size()));
  return Design(experiment, std::move(rows), std::move(withinConditions), std::move(betweenCells));
}

}  // namespace tlab::study
