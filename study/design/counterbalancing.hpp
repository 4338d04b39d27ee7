#pragma once
// The design of an experiment: which sequence of condition blocks each participant slot gets.
// The within conditions are the combinations of the within factors' levels (first factor slowest);
// the counterbalancing method orders them into rows (Latin square, Williams, Graeco-Latin, all
// permutations, seeded random, or fixed), and between-subject cells are crossed with the rows:
// slot s gets between cell s mod B and row (s div B) mod rows, so any multiple of B·rows
// participants is balanced.
#include <map>
#include <string>
#include <vector>

#include "study/design/design_error.hpp"
#include "study/design/experiment.hpp"
#include "study/design/latin_square.hpp"

namespace tlab::study {

// One block's condition: a level index per factor, in Experiment::factors order (between
// factors included, so a condition names the participant's whole cell).
struct Condition {
  std::vector<int> levels;
};

struct SlotDesign {
  int slot = 0;
  int row = 0;
  int betweenCell = 0;
  std::vector<Condition> blocks;
};

class Design {
 public:
  Design(const Experiment& experiment, OrderTable rows, std::vector<std::vector<int>> withinConditions,
         std::vector<std::vector<int>> betweenCells);

  std::size_t rowCount() const { return rows_.size(); }
  std::size_t betweenCellCount() const { return betweenCells_.size(); }
  std::size_t blocksPerRow() const { return rows_.empty() ? 0 : rows_.front().size(); }
  // Participants needed for a balanced design: a multiple of rows × between cells.
  std::size_t balancedMultiple() const { return rowCount() * betweenCellCount(); }
  SlotDesign slot(int slot) const;

  // "method=alpha, scene=pretzel"
  std::string describe(const Condition& condition) const;
  // factor name → level name
  std::map<std::string, std::string> levelNames(const Condition& condition) const;

 private:
  const Experiment* experiment_;
  OrderTable rows_;  // rows of within-condition indices (GraecoLatin: indices into withinConditions_ too)
  std::vector<std::vector<int>> withinConditions_;  // level index per within factor
  std::vector<std::vector<int>> betweenCells_;      // level index per between factor
};

// Throws DesignError when the method does not fit the factors (e.g. Graeco-Latin without two
// within factors of the same number of levels).
Design makeDesign(const Experiment& experiment);

}  // namespace tlab::study
