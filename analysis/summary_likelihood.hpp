#pragma once
// Log-likelihood of a published summary — n, the sample mean m and the sample variance v of n
// independent observations — under a model that predicts their mean mu and variance sigma2,
// taking the observations as normal: m ~ N(mu, sigma2/n) and (n-1) v / sigma2 ~ chi2(n-1),
// independent of each other (Cochran's theorem). This is what a paper's table of means and
// variances per condition says about a model; maximising its sum over conditions fits the model
// to the published results.
#include <cstddef>

namespace tlab::analysis {

double summaryLogLikelihood(std::size_t n, double m, double v, double mu, double sigma2);

}  // namespace tlab::analysis
