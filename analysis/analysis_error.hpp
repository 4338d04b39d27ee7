#pragma once
// AnalysisError: the one exception type of tlab_analysis. Its message is a single line that names
// what is wrong and where (file:line, column, subject, cell), ready to be printed as
// "tlab: error: <message>".
#include <stdexcept>
#include <string>

namespace tlab::analysis {

class AnalysisError : public std::runtime_error {
 public:
  explicit AnalysisError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace tlab::analysis
