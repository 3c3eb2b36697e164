#pragma once
// The benchmark suites by name (`rollsim bench accuracy | stability`), their sizes, and the run of a suite's cases,
// each in its own process.
#include <functional>
#include <string>
#include <vector>

#include "bench/Verdict.h"

namespace rollsim::bench {

/// "accuracy", "stability".
const std::vector<std::string>& suite_names();
/// "tiny", "quick", "full"; throws std::invalid_argument naming the choices.
SuiteSize suite_size(const std::string& name);
/// The cases of suite `name` at `size`, only those of `family` when it is not empty; throws std::invalid_argument
/// for an unknown suite or a family the suite does not have.
std::vector<SuiteCase> suite_cases(const std::string& name, SuiteSize size, const std::string& family = "");

/// Runs every case in its own process (killed after `timeout_s`), calling `progress` after each, and judges them.
std::vector<CaseResult> run_suite(
    const std::vector<SuiteCase>& cases, double timeout_s,
    const std::function<void(size_t done, const SuiteCase&, const CaseOutcome&)>& progress);

}  // namespace rollsim::bench
