#pragma once
// Validation of a partition: every problem reported with a path, and the automatic repair of subdomains made
// of disconnected pieces (a piece joined to the rest by no shared edge/face would add rigid modes that the
// geometric kernel of RigidModes.h cannot see).
#include <string>
#include <vector>

#include "mesh/Mesh.h"
#include "partition/Partition.h"

namespace rollsim {

/// Wrong map length, no subdomain, out-of-range ids, empty subdomains, subdomains of several pieces.
/// Paths are prefixed by `path`: "<path>.map", "<path>.map[<element>]", "<path>.subdomains[<id>]".
std::vector<PartitionProblem> check_partition(const Mesh& mesh, const Partition& p,
                                              const std::string& path = "partition");

/// One problem per class (empty subdomains, subdomains of several pieces, …): the first of each, saying which other
/// subdomains share it and how many in all — for messages, where a 400-subdomain mistake must not print 400 lines.
/// Problems that name no subdomain are kept as they are.
std::vector<PartitionProblem> one_per_class(const std::vector<PartitionProblem>& problems);

/// The facet-connected pieces of every subdomain (element lists), largest first.
std::vector<std::vector<std::vector<int>>> subdomain_pieces(const Mesh& mesh, const Partition& p);

/// Gives every extra piece of a disconnected subdomain a new id (appended); the largest piece keeps the id.
/// Returns one warning per subdomain split, saying so.
std::vector<std::string> split_disconnected(const Mesh& mesh, Partition& p);

}  // namespace rollsim
