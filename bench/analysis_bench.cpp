// Speed of the statistics on study-sized and larger inputs (never measured in the tests).
#include <benchmark/benchmark.h>

#include <random>

#include "analysis/anova.hpp"
#include "analysis/mixed_model.hpp"
#include "analysis/rank_tests.hpp"
#include "analysis/ttest.hpp"

namespace {

using namespace tlab::analysis;

std::vector<double> normalSample(std::size_t n, double mean, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> dist(mean, 1.0);
  std::vector<double> x(n);
  for (auto& v : x) v = dist(rng);
  return x;
}

void BM_WelchTTest(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto x = normalSample(n, 0.0, 1);
  const auto y = normalSample(n, 0.1, 2);
  for (auto _ : state) benchmark::DoNotOptimize(welchTTest(x, y, Alternative::TwoSided));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(2 * n));
}
BENCHMARK(BM_WelchTTest)->Arg(100)->Arg(100000);

// Mixed ANOVA: 2 groups × (2 × 3 within cells), the size of a typical perception study.
void BM_MixedAnova(benchmark::State& state) {
  const auto subjects = static_cast<std::size_t>(state.range(0));
  AnovaDesign d;
  d.dv = "y";
  d.between = {{"group", {"a", "b"}}};
  d.within = {{"style", {"s1", "s2"}}, {"scene", {"c1", "c2", "c3"}}};
  const auto values = normalSample(subjects * 6, 10.0, 3);
  d.y.resize(static_cast<Eigen::Index>(subjects), 6);
  for (std::size_t s = 0; s < subjects; ++s) {
    d.subjects.push_back(std::to_string(s));
    d.betweenLevels.push_back({s % 2});
    for (std::size_t c = 0; c < 6; ++c) d.y(static_cast<Eigen::Index>(s), static_cast<Eigen::Index>(c)) = values[s * 6 + c];
  }
  for (auto _ : state) benchmark::DoNotOptimize(anova(d));
}
BENCHMARK(BM_MixedAnova)->Arg(16)->Arg(1000);

void BM_ExactMannWhitney(benchmark::State& state) {
  const auto x = normalSample(49, 0.0, 4);
  const auto y = normalSample(49, 0.3, 5);
  for (auto _ : state) benchmark::DoNotOptimize(mannWhitneyTest(x, y, Alternative::TwoSided));
}
BENCHMARK(BM_ExactMannWhitney);

// Mixed models on 10 000 trials: 100 participants × 100 stimuli, fully crossed, a 2-level method
// within both (the size of a large online study). Range 0: 0 = lmer (REML), 1 = glmer (Laplace).
Table crossedTrials(std::size_t participants, std::size_t stimuli, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> pe(participants), se(stimuli);
  for (auto& v : pe) v = 0.3 * normal(rng);
  for (auto& v : se) v = 0.2 * normal(rng);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Table t("bench", {"participant", "stimulus", "method", "rt", "correct"});
  std::size_t line = 2;
  for (std::size_t p = 0; p < participants; ++p)
    for (std::size_t s = 0; s < stimuli; ++s) {
      const bool smart = (p + s) % 2 == 0;
      const double eta = pe[p] + se[s] + (smart ? -0.1 : 0.0);
      const double rt = std::exp(1.5 + eta + 0.3 * normal(rng));
      const bool correct = uniform(rng) < 1.0 / (1.0 + std::exp(-(0.8 - 2.0 * eta)));
      t.addRow({"p" + std::to_string(p), "s" + std::to_string(s), smart ? "smart" : "alpha", std::to_string(rt), correct ? "1" : "0"}, line++);
    }
  return t;
}

void BM_MixedModel10000(benchmark::State& state) {
  const Table t = crossedTrials(100, 100, 7);
  MixedModelRequest request;
  const bool binomial = state.range(0) == 1;
  request.formula = binomial ? "correct ~ method + (1 | participant) + (1 | stimulus)" : "log(rt) ~ method + (1 | participant) + (1 | stimulus)";
  request.family = binomial ? MixedFamily::Binomial : MixedFamily::Gaussian;
  int evaluations = 0;
  for (auto _ : state) {
    const MixedModelResult r = fitMixedModel(t, request);
    evaluations = r.evaluations;
    benchmark::DoNotOptimize(r.fixedEffects);
  }
  state.counters["deviance_evaluations"] = evaluations;
}
BENCHMARK(BM_MixedModel10000)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
