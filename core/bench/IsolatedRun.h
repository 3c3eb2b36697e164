#pragma once
// A benchmark case run in a child process (fork): its peak memory is its own (getrusage of the child), a crash or
// a hang ends that case only — reported as `crashed` (the signal) or `timeout` (slower than the suite allows).
#include "bench/RunCase.h"

namespace rollsim::bench {

/// run_case in a forked child, killed after `timeout_s` seconds; the outcome's peak_rss_mb is the child's maximum
/// resident set: the pages it touched or inherited as anonymous memory (a few MB before the case starts).
CaseOutcome run_case_isolated(const SuiteCase& c, double timeout_s);

}  // namespace rollsim::bench
