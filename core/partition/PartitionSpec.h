#pragma once
// How a partition is asked for: the CLI / project spelling ("4x4", "2x2x1", "metis:16") or an explicit map.
#include <array>
#include <string>
#include <vector>

#include "mesh/Mesh.h"
#include "partition/Partition.h"

namespace rollsim {

enum class PartitionKind { Structured, Metis, Explicit };

struct PartitionSpec {
  PartitionKind kind = PartitionKind::Structured;
  std::array<int, 3> slices{1, 1, 1};  // Structured: pieces along x, y, z
  int axes = 2;                        // Structured: how many counts were written (2 or 3)
  int parts = 1;                       // Metis: number of subdomains
  std::vector<int> map;                // Explicit: element -> subdomain (a GUI painter's output)
  int num_subdomains = -1;             // Explicit: declared count; -1 = largest id + 1
};

/// Parses "AxB", "AxBxC" (slice counts along x, y, z; 'x' or 'X') and "metis:N". Throws PartitionError
/// (path "partition") with a message that says what was expected.
PartitionSpec parse_partition_spec(const std::string& text);

/// The spelling parse_partition_spec reads back ("explicit" for a map).
std::string to_string(const PartitionSpec& spec);

/// "" when `spec` asks for no more subdomains than `mesh` has elements (each needs one), else why not — checked in
/// 64 bits before anything is allocated (a "40000x40000" or an explicit id of 1e6 on a small body).
std::string oversized_partition(const Mesh& mesh, const PartitionSpec& spec);

/// The partition a spec asks for on this mesh (not yet validated: see check_partition).
Partition make_partition(const Mesh& mesh, const PartitionSpec& spec);

}  // namespace rollsim
