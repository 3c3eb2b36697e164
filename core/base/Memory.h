#pragma once
// How much memory this process may still take, for refusing a factorization that cannot fit before it is tried
// (an allocation that fails half-way through CHOLMOD was an "internal error"; under an address-space limit the
// kernel refuses it, without one the OOM killer ends the process with no word).
#include <string>

namespace rollsim {

/// Physical memory of this machine [bytes] (sysconf); 0 when unknown.
double physical_memory_bytes();

/// What this process can still allocate [bytes]: the smaller of the machine's available memory (MemAvailable) and
/// what the address-space limit (ulimit -v) leaves above the process's current size; infinity when neither is known.
double memory_left_bytes();

/// Which of the two bounds memory_left_bytes() took, for messages: "the address-space limit (ulimit -v)" or "the
/// machine's available memory".
std::string memory_left_source();

/// "1.2 GB".
std::string gigabytes(double bytes);

}  // namespace rollsim
