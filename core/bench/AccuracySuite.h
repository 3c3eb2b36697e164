#pragma once
// The accuracy suite (`rollsim bench accuracy`): run time against error for every solver mode, preconditioner and
// update policy, over mesh refinement and CG tolerance, on problems with a known answer.
#include <vector>

#include "bench/SuiteCase.h"

namespace rollsim::bench {

/// cantilever (tip deflection; reference: direct on a 2× finer mesh), kirsch (σ_yy at the hole; reference: direct
/// on a 2× finer mesh), hertz (peak pressure; Hertz's closed form), plastic (the paper's Example 2, contact force;
/// reference: direct on a 1.5× finer mesh in 40 increments;
/// update policies always and selective; not in the tiny size).
std::vector<SuiteCase> accuracy_cases(SuiteSize size);

}  // namespace rollsim::bench
