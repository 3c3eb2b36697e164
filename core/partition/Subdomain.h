#pragma once
// One subdomain of a body with its own numbering (paper §2; DESIGN.md: every group keeps a local numbering
// and a local-to-global map, so that its matrices can be handed on as they are).
#include <memory>
#include <string>
#include <vector>

#include "model/DofMap.h"
#include "model/Model.h"
#include "partition/Partition.h"

namespace rollsim {

struct Subdomain {
  int id = 0;
  Body body;                     // local mesh: this subdomain's elements and nodes only; material as the body's
  std::vector<int> elements;     // local element -> body element (ascending)
  std::vector<int> nodes;        // local node -> body node (ascending)
  std::unique_ptr<DofMap> dofs;  // local free dofs; the body's prescribed dofs stay prescribed (eliminated)
  std::vector<int> free_dofs;    // local equation -> body equation (ascending, since both are node-major)

  /// Local node of a body node, or -1.
  int local_node(int body_node) const;
  /// Local equation of (body node, component), or -1 (not in this subdomain, or prescribed).
  int local_equation(int body_node, int comp) const;
};

/// Splits a body along a (valid) partition. Node sets, element sets and surfaces are not carried over.
std::vector<Subdomain> extract_subdomains(const Body& body, const DofMap& body_dofs, const Partition& p);

}  // namespace rollsim
