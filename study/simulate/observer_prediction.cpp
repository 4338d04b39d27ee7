#include "study/simulate/observer_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <Eigen/Dense>

namespace tlab::study {

namespace {

struct Quadrature {
  std::vector<double> nodes, weights;
};

// Gauss-Hermite rule for E[f(X)], X ~ N(0, 1), by Golub & Welsch (1969): the nodes are the
// eigenvalues of the Jacobi matrix of the probabilists' Hermite polynomials (off-diagonal √k),
// the weights the squared first components of its normalised eigenvectors.
Quadrature standardNormalQuadrature(int n) {
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(n, n);
  for (int k = 1; k < n; ++k) j(k, k - 1) = j(k - 1, k) = std::sqrt(double(k));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(j);
  Quadrature q;
  for (int k = 0; k < n; ++k) {
    q.nodes.push_back(solver.eigenvalues()(k));
    q.weights.push_back(solver.eigenvectors()(0, k) * solver.eigenvectors()(0, k));
  }
  return q;
}

double normalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// P(X ≤ limit) for X log-normal with median `median` and log-sd sigma (sigma 0: a step).
double logNormalBelow(double limit, double median, double sigma) {
  if (limit <= 0.0) return 0.0;
  if (sigma <= 0.0) return median <= limit ? 1.0 : 0.0;
  return normalCdf((std::log(limit) - std::log(median)) / sigma);
}

// P(Σ X_i ≤ limit) for independent log-normal X_i with these medians and log-sd sigma, by the
// log-normal of equal mean and variance (Fenton 1960).
double logNormalSumBelow(double limit, const std::vector<double>& medians, double sigma) {
  double sum = 0.0, sumSquares = 0.0;
  for (const double m : medians) {
    sum += m;
    sumSquares += m * m;
  }
  if (sigma <= 0.0) return sum <= limit ? 1.0 : 0.0;
  const double mean = sum * std::exp(sigma * sigma / 2.0);
  const double variance = sumSquares * std::exp(sigma * sigma) * (std::exp(sigma * sigma) - 1.0);
  const double s2 = std::log(1.0 + variance / (mean * mean));
  return logNormalBelow(limit, std::exp(std::log(mean) - s2 / 2.0), std::sqrt(s2));
}

// p_t(s) for every question of one participant (grouped by trial, in order).
std::vector<double> correctProbabilities(const ObserverParams& p, const std::vector<const PredictionQuestion*>& qs, double skill) {
  std::vector<double> out;
  std::map<int, std::vector<double>> trialMedians;  // medians so far per trial
  for (const PredictionQuestion* q : qs) {
    const double median = (p.baseSeconds + p.slowSeconds * (1.0 - q->visibility)) / std::sqrt(skill);
    auto& medians = trialMedians[q->trial];
    medians.push_back(median);
    double answered = logNormalBelow(q->questionLimitSeconds, median, p.rtSigma);
    if (q->trialLimitSeconds)
      answered = std::pow(1.0 - p.giveUpShare, double(medians.size())) *
                 std::min(answered, logNormalSumBelow(*q->trialLimitSeconds, medians, p.rtSigma));
    else
      answered *= 1.0 - p.giveUpShare;
    const double knows = (1.0 - p.lapse) / (1.0 + std::exp(-p.sensitivity * (skill * q->visibility - p.threshold)));
    out.push_back(answered * (knows + (1.0 - knows) * q->guessCorrect));
  }
  return out;
}

}  // namespace

PredictedProportion predictProportionCorrect(const ObserverParams& params, const std::vector<PredictionQuestion>& questions) {
  static const Quadrature rule = standardNormalQuadrature(24);
  std::map<int, std::vector<const PredictionQuestion*>> byParticipant;
  for (const auto& q : questions) byParticipant[q.participant].push_back(&q);
  for (auto& [participant, qs] : byParticipant)
    std::stable_sort(qs.begin(), qs.end(), [](const auto* a, const auto* b) { return std::pair(a->trial, a->order) < std::pair(b->trial, b->order); });
  double sum = 0.0, sumSquares = 0.0, noise = 0.0;
  for (const auto& [participant, qs] : byParticipant)
    for (std::size_t k = 0; k < rule.nodes.size(); ++k) {
      const auto p = correctProbabilities(params, qs, std::exp(params.skillSpread * rule.nodes[k]));
      double total = 0.0, binomial = 0.0;
      for (const double pt : p) {
        total += pt;
        binomial += pt * (1.0 - pt);
      }
      const double n = double(p.size());
      sum += rule.weights[k] * total / n;
      sumSquares += rule.weights[k] * (total / n) * (total / n);
      noise += rule.weights[k] * binomial / (n * n);
    }
  PredictedProportion out;
  out.participants = int(byParticipant.size());
  if (out.participants == 0) return out;
  const double j = double(out.participants);
  out.mean = sum / j;
  out.variance = std::max(0.0, sumSquares / j - out.mean * out.mean) + noise / j;
  return out;
}

}  // namespace tlab::study
