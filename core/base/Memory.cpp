#include "base/Memory.h"

#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>

namespace rollsim {

namespace {
/// A "Name: value kB" line of a /proc file [bytes]; -1 when absent.
double proc_kilobytes(const char* file, const std::string& name) {
  std::ifstream in(file);
  const std::string key = name + ":";
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key, 0) == 0) return std::atof(line.c_str() + key.size()) * 1024;  // "VmSize:\t  123456 kB"
  return -1;
}

double address_space_left() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
    return std::numeric_limits<double>::infinity();
  const double size = proc_kilobytes("/proc/self/status", "VmSize");
  return static_cast<double>(limit.rlim_cur) - (size > 0 ? size : 0);
}

double available() {
  const double a = proc_kilobytes("/proc/meminfo", "MemAvailable");
  return a > 0 ? a : std::numeric_limits<double>::infinity();
}
}  // namespace

double physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && size > 0 ? static_cast<double>(pages) * static_cast<double>(size) : 0.0;
}

double memory_left_bytes() { return std::min(address_space_left(), available()); }

std::string memory_left_source() {
  return address_space_left() < available() ? "the address-space limit (ulimit -v)" : "the machine's available memory";
}

std::string gigabytes(double bytes) {
  char s[32];
  std::snprintf(s, sizeof s, bytes < 1e8 ? "%.3f GB" : "%.1f GB", bytes / 1e9);
  return s;
}

void keep_freed_memory_for_reuse() {
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kKeptBlockBytes));
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(kKeptBlockBytes));
}

}  // namespace rollsim
