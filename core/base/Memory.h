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

/// Keeps memory a solve frees for the next one to reuse (glibc's allocator): blocks below kKeptBlockBytes come from
/// the heap instead of fresh mappings, and up to that much freed at the heap's top stays mapped. UMFPACK allocates its
/// numeric workspace afresh at every factorization and the triplets of a global matrix are rebuilt: with glibc's
/// defaults each came from a new mapping, zeroed and faulted in page by page (the 2D 140 × 25 pass under `direct` +
/// `always`: 783 k page faults, half of its time; docs/BENCHMARKS.md "Allocator"). Called once, at the start of main.
void keep_freed_memory_for_reuse();
inline constexpr long kKeptBlockBytes = 256L << 20;

}  // namespace rollsim
