#pragma once
// convergence.csv: one row per Newton iteration (Results::newton), for plots of the residual history.
#include <string>

#include "analysis/Results.h"

namespace rollsim {

/// The CSV text: header, then increment, attempt, iteration, load_factor, residual, relative_residual,
/// correction, refactored_groups, contact_changes, cg_iterations.
std::string convergence_csv(const Results& results);

}  // namespace rollsim
