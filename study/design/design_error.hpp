#pragma once
#include <stdexcept>

namespace tlab::study {

// A design that cannot be built (e.g. no Graeco-Latin square of order 6).
class DesignError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace tlab::study
