// Counterbalancing: Latin squares (each level once per row and column), Williams designs (each
// ordered pair adjacent exactly once for even n, twice in the doubled odd design), Graeco-Latin
// orthogonality, permutations, seeded random orders, and the two example designs: Carnecky's
// method × scene Graeco-Latin assignment and Elmqvist's 384 task records.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "study/design/counterbalancing.hpp"
#include "study/design/experiment_file.hpp"
#include "study/design/graeco_latin_square.hpp"
#include "study/design/order_permutations.hpp"
#include "study/design/session_plan.hpp"
#include "study/design/williams_design.hpp"
#include "tests/study/study_test_support.hpp"

using namespace tlab::study;
using tlab::testing::example;
using tlab::testing::studyData;

namespace {

std::map<std::pair<int, int>, int> adjacentPairs(const OrderTable& rows) {
  std::map<std::pair<int, int>, int> pairs;
  for (const auto& row : rows)
    for (std::size_t i = 0; i + 1 < row.size(); ++i) ++pairs[{row[i], row[i + 1]}];
  return pairs;
}

bool everyLevelOncePerRow(const OrderTable& rows, int n) {
  for (const auto& row : rows)
    if (std::set<int>(row.begin(), row.end()).size() != std::size_t(n) || row.size() != std::size_t(n)) return false;
  return true;
}

}  // namespace

TEST(LatinSquare, EveryLevelOncePerRowAndColumn) {
  for (int n = 1; n <= 9; ++n) {
    const OrderTable square = cyclicLatinSquare(n);
    ASSERT_EQ(square.size(), std::size_t(n));
    EXPECT_TRUE(isLatinSquare(square)) << n;
  }
  EXPECT_FALSE(isLatinSquare({{0, 1}, {0, 1}}));  // a column repeats a level
  EXPECT_FALSE(isLatinSquare({{0, 0}, {1, 1}}));  // a row repeats a level
  EXPECT_THROW(cyclicLatinSquare(0), DesignError);
}

TEST(WilliamsDesign, EvenOrdersHaveEveryOrderedPairAdjacentExactlyOnce) {
  for (int n : {2, 4, 6, 8, 10}) {
    const OrderTable rows = williamsDesign(n);
    ASSERT_EQ(rows.size(), std::size_t(n));
    EXPECT_TRUE(isLatinSquare(rows)) << n;
    const auto pairs = adjacentPairs(rows);
    EXPECT_EQ(pairs.size(), std::size_t(n * (n - 1))) << n;
    for (const auto& [pair, count] : pairs) EXPECT_EQ(count, 1) << n << ": " << pair.first << "→" << pair.second;
  }
}

TEST(WilliamsDesign, OddOrdersAreDoubledAndBalancedTwice) {
  for (int n : {3, 5, 7}) {
    const OrderTable rows = williamsDesign(n);
    ASSERT_EQ(rows.size(), std::size_t(2 * n));
    EXPECT_TRUE(everyLevelOncePerRow(rows, n));
    const auto pairs = adjacentPairs(rows);
    EXPECT_EQ(pairs.size(), std::size_t(n * (n - 1))) << n;
    for (const auto& [pair, count] : pairs) EXPECT_EQ(count, 2) << n;
    for (int position = 0; position < n; ++position) {  // each level twice in each position
      std::map<int, int> counts;
      for (const auto& row : rows) ++counts[row[std::size_t(position)]];
      for (const auto& [level, count] : counts) EXPECT_EQ(count, 2);
    }
  }
}

TEST(GraecoLatinSquare, IsOrthogonalForTheOrdersItBuilds) {
  for (int n : {1, 3, 4, 5, 7, 8, 9, 11}) {
    const GraecoLatinSquare square = graecoLatinSquare(n);
    EXPECT_TRUE(isGraecoLatin(square)) << n;
  }
  GraecoLatinSquare notOrthogonal{cyclicLatinSquare(3), cyclicLatinSquare(3)};
  EXPECT_FALSE(isGraecoLatin(notOrthogonal));
  EXPECT_THROW(graecoLatinSquare(2), DesignError);
  EXPECT_THROW(graecoLatinSquare(6), DesignError);
}

TEST(OrderPermutations, AllPermutationsAndSeededRandomOrders) {
  const OrderTable all = allPermutations(4);
  EXPECT_EQ(all.size(), 24u);
  EXPECT_EQ(std::set<std::vector<int>>(all.begin(), all.end()).size(), 24u);
  EXPECT_THROW(allPermutations(9), DesignError);
  const auto a = seededRandomOrder(6, 42), b = seededRandomOrder(6, 42), c = seededRandomOrder(6, 43);
  EXPECT_EQ(a, b);
  EXPECT_EQ(std::set<int>(a.begin(), a.end()).size(), 6u);
  bool differs = a != c;
  for (std::uint64_t s = 44; s < 50 && !differs; ++s) differs = seededRandomOrder(6, s) != a;
  EXPECT_TRUE(differs);
  // Portable: the same seed gives this order on every platform (SeededRandom maps bits itself).
  EXPECT_EQ(seededRandomOrder(4, 1), seededRandomOrder(4, 1));
}

TEST(ExampleDesigns, CarneckyGivesEachParticipantEachMethodAndSceneOnceAndIsBalanced) {
  const Experiment e = readExperimentFile(example("carnecky2013.toml"));
  const Design design = makeDesign(e);
  EXPECT_EQ(e.participants, 36);
  EXPECT_EQ(design.blocksPerRow(), 3u);
  EXPECT_EQ(e.participants % int(design.balancedMultiple()), 0);
  std::map<std::tuple<int, std::string, std::string>, int> byPosition;  // (position, factor, level)
  std::map<std::pair<std::string, std::string>, int> pairs;
  for (int slot = 0; slot < e.participants; ++slot) {
    const SessionPlan plan = makeSessionPlan(e, design, slot);
    std::set<std::string> methods, scenes;
    for (std::size_t b = 0; b < plan.design.blocks.size(); ++b) {
      const auto levels = design.levelNames(plan.design.blocks[b]);
      methods.insert(levels.at("method"));
      scenes.insert(levels.at("scene"));
      ++byPosition[{int(b), "method", levels.at("method")}];
      ++byPosition[{int(b), "scene", levels.at("scene")}];
      ++pairs[{levels.at("method"), levels.at("scene")}];
    }
    EXPECT_EQ(methods.size(), 3u) << slot;
    EXPECT_EQ(scenes.size(), 3u) << slot;
    // Tasks in a fixed order, one per block.
    std::vector<std::string> taskOrder;
    for (const auto& t : plan.trials)
      if (taskOrder.empty() || taskOrder.back() != t.taskId) taskOrder.push_back(t.taskId);
    EXPECT_EQ(taskOrder, (std::vector<std::string>{"layer-index", "follow-boundary", "nearest-point"}));
    for (const auto& t : plan.trials) EXPECT_EQ(t.trialTimeLimitSeconds.value_or(0), 120.0);
  }
  for (const auto& [key, count] : byPosition) EXPECT_EQ(count, 12);
  EXPECT_EQ(pairs.size(), 9u);
  for (const auto& [pair, count] : pairs) EXPECT_EQ(count, 12) << pair.first << "/" << pair.second;
}

TEST(ExampleDesigns, ElmqvistGives384TaskRecordsWithLatinSquareOrder) {
  const Experiment e = readExperimentFile(example("elmqvist.toml"));
  const Design design = makeDesign(e);
  EXPECT_EQ(e.participants, 16);
  int records = 0;
  std::map<std::pair<int, std::string>, int> conditionAtPosition;
  std::map<std::pair<std::string, std::string>, int> perTaskCondition;
  for (int slot = 0; slot < e.participants; ++slot) {
    const SessionPlan plan = makeSessionPlan(e, design, slot);
    for (std::size_t b = 0; b < plan.design.blocks.size(); ++b) ++conditionAtPosition[{int(b), design.describe(plan.design.blocks[b])}];
    for (const auto& t : plan.trials) {
      if (t.phase != Phase::Test) continue;
      ++records;
      ++perTaskCondition[{t.taskId, t.levels.at("transparency")}];
      EXPECT_EQ(t.levels.at("scenario"), (t.taskId == "T1" || t.taskId == "T2") ? "abstract" : "walkthrough");
    }
  }
  EXPECT_EQ(records, 384);
  EXPECT_EQ(conditionAtPosition.size(), 16u);  // 4 conditions × 4 positions
  for (const auto& [key, count] : conditionAtPosition) EXPECT_EQ(count, 4);
  for (const auto& [key, count] : perTaskCondition) EXPECT_EQ(count, 16 * 3) << key.first << " " << key.second;
}

TEST(ExampleDesigns, TinyWilliamsDesignIsCarryOverBalanced) {
  const Experiment e = readExperimentFile(studyData("tiny.toml"));
  const Design design = makeDesign(e);
  EXPECT_EQ(design.rowCount(), 4u);
  std::map<std::pair<std::string, std::string>, int> adjacent;
  for (int slot = 0; slot < 4; ++slot) {
    const SlotDesign d = design.slot(slot);
    for (std::size_t b = 0; b + 1 < d.blocks.size(); ++b) ++adjacent[{design.describe(d.blocks[b]), design.describe(d.blocks[b + 1])}];
  }
  EXPECT_EQ(adjacent.size(), 12u);
  for (const auto& [pair, count] : adjacent) EXPECT_EQ(count, 1);
}

TEST(ExampleDesigns, BetweenFactorsCycleWithTheRows) {
  const Experiment e = parseExperiment(R"(
id = "between"
participants = 8
counterbalancing = "latin-square"
[[factors]]
name = "group"
kind = "between"
levels = ["a", "b"]
[[factors]]
name = "method"
levels = ["x", "y"]
[[tasks]]
task = "layer-index"
)", "between.toml");
  const Design design = makeDesign(e);
  EXPECT_EQ(design.balancedMultiple(), 4u);
  std::map<std::pair<std::string, std::string>, int> cells;  // (group, first method)
  for (int slot = 0; slot < 8; ++slot) {
    const SlotDesign d = design.slot(slot);
    ++cells[{design.levelNames(d.blocks[0]).at("group"), design.levelNames(d.blocks[0]).at("method")}];
    EXPECT_EQ(design.levelNames(d.blocks[0]).at("group"), design.levelNames(d.blocks[1]).at("group"));
  }
  for (const auto& [cell, count] : cells) EXPECT_EQ(count, 2);
  EXPECT_EQ(cells.size(), 4u);
}
