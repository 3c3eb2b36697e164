#pragma once
// A number as the run's messages write it: four significant digits (%.4g).
#include <cstdio>
#include <string>

namespace rollsim {

inline std::string four_digits(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace rollsim
