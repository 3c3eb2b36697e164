#pragma once
#include <stdexcept>

namespace rollsim {

/// The model cannot be solved as given (a body free to move, contact that cannot hold a floating body, a strategy
/// that cannot handle the model): bad input, reported to the user with exit code 2.
struct AnalysisError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace rollsim
