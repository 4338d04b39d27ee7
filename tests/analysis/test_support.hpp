#pragma once
// Shared helpers of the analysis tests.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <string>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis::testing {

// |actual - expected| <= rel · |expected|: "agrees to about -log10(rel) significant digits".
inline ::testing::AssertionResult relativelyNear(double actual, double expected, double rel) {
  const double err = std::fabs(actual - expected);
  if (err <= rel * std::fabs(expected)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "actual " << std::scientific << std::setprecision(17) << actual
                                       << " vs expected " << expected << " (relative error "
                                       << err / std::fabs(expected) << " > " << rel << ")";
}

// Runs f, expects an AnalysisError whose message contains every fragment.
template <class F>
::testing::AssertionResult throwsWithMessage(F&& f, std::initializer_list<const char*> fragments) {
  try {
    f();
  } catch (const AnalysisError& e) {
    const std::string message = e.what();
    for (const char* fragment : fragments)
      if (message.find(fragment) == std::string::npos)
        return ::testing::AssertionFailure() << "message '" << message << "' lacks '" << fragment << "'";
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "no AnalysisError thrown";
}

}  // namespace tlab::analysis::testing
