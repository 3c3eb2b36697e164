#include "bench/SuiteCase.h"

#include <cstdio>

namespace rollsim::bench {

std::string SuiteCase::tolerance_label() const {
  if (cg_tolerance <= 0) return "";
  char s[32];
  std::snprintf(s, sizeof s, "/tol=%.0e", cg_tolerance);
  return s;
}

}  // namespace rollsim::bench
