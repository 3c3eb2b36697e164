#pragma once
// The stability stress suite (`rollsim bench stability`): the solvers pushed where they break — stiffness ratios
// between bodies, near-incompressibility, slender and floating subdomains, subdomains touching the supports at a
// node or an edge, grazing contact and tiny gaps, distorted meshes, tight CG tolerances. Each case states the error
// it must stay within; an answer beyond it is reported, with its likely cause, never passed silently.
#include <vector>

#include "bench/SuiteCase.h"

namespace rollsim::bench {

std::vector<SuiteCase> stability_cases(SuiteSize size);

}  // namespace rollsim::bench
