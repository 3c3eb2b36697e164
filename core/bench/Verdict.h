#pragma once
// A case judged: its error against the reference (its closed form, or the value of its reference case), and what
// happened in words — within its bound, beyond it (a wrong answer, named with its likely cause), or how it failed.
#include <string>
#include <vector>

#include "bench/RunCase.h"

namespace rollsim::bench {

/// ok: converged within its bound; wrong: converged beyond its bound (said, with the likely cause); failed: did not
/// converge, was refused, or ran past the suite's time limit, with the reason; broken: no answer and no reason (a
/// crash, NaN in a converged answer) — the only kind the suites must never show.
enum class Verdict { ok, wrong, failed, broken };
const char* to_string(Verdict v);

struct CaseResult {
  SuiteCase c;
  CaseOutcome o;
  double reference = CaseOutcome::nan;
  double error = CaseOutcome::nan;  // |value − reference| / |reference|
  Verdict verdict = Verdict::broken;
  std::string words;  // the verdict for a reader
};

/// Judges outcomes[i] of cases[i]; a reference case is found by name among `cases`.
std::vector<CaseResult> judge(const std::vector<SuiteCase>& cases, const std::vector<CaseOutcome>& outcomes);

}  // namespace rollsim::bench
