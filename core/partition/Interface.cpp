#include "partition/Interface.h"

#include <algorithm>
#include <numeric>

#include "partition/DualGraph.h"

namespace rollsim {

const char* to_string(Multipliers m) {
  switch (m) {
    case Multipliers::NonRedundant:
      return "non-redundant";
    case Multipliers::FullyRedundant:
      return "fully redundant";
    case Multipliers::FacePairs:
      return "face pairs";
  }
  return "?";
}

namespace {
/// (node, subdomain) for every element node, sorted and unique.
std::vector<std::pair<int, int>> node_subdomains(const Mesh& m, const Partition& p) {
  std::vector<std::pair<int, int>> ns;
  ns.reserve(m.connectivity.size());
  for (int e = 0; e < m.num_elements(); ++e)
    for (int k = 0; k < m.nodes_per_elem(); ++k) ns.emplace_back(m.element(e)[k], p.element_subdomain[e]);
  std::sort(ns.begin(), ns.end());
  ns.erase(std::unique(ns.begin(), ns.end()), ns.end());
  return ns;
}

/// (node, (a, b)) for every node of a facet between subdomains a < b, sorted and unique.
std::vector<std::pair<int, std::pair<int, int>>> facet_pairs(const Mesh& m, const Partition& p) {
  std::vector<std::pair<int, std::pair<int, int>>> fp;
  for (const SharedFacet& f : shared_facets(m)) {
    const int a = p.element_subdomain[f.a], b = p.element_subdomain[f.b];
    if (a == b) continue;
    for (int k = 0; k < f.num_nodes; ++k) fp.push_back({f.nodes[k], {std::min(a, b), std::max(a, b)}});
  }
  std::sort(fp.begin(), fp.end());
  fp.erase(std::unique(fp.begin(), fp.end()), fp.end());
  return fp;
}

/// Union-find over the positions of n.subdomains.
struct Forest {
  std::vector<int> parent;
  explicit Forest(size_t k) : parent(k) { std::iota(parent.begin(), parent.end(), 0); }
  int root(int i) { return parent[i] == i ? i : parent[i] = root(parent[i]); }
  bool join(int i, int j) {
    const int a = root(i), b = root(j);
    if (a == b) return false;
    parent[std::max(a, b)] = std::min(a, b);
    return true;
  }
};

int position(const InterfaceNode& n, int s) {
  return static_cast<int>(std::lower_bound(n.subdomains.begin(), n.subdomains.end(), s) - n.subdomains.begin());
}

/// Face pairs (all, or only those joining two trees), then every remaining tree tied to the lowest subdomain.
std::vector<std::pair<int, int>> tree_pairs(const InterfaceNode& n, bool keep_all_face_pairs) {
  Forest forest(n.subdomains.size());
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [a, b] : n.face_pairs)
    if (forest.join(position(n, a), position(n, b)) || keep_all_face_pairs) pairs.emplace_back(a, b);
  for (size_t i = 1; i < n.subdomains.size(); ++i)
    if (forest.join(0, static_cast<int>(i))) pairs.emplace_back(n.subdomains[0], n.subdomains[i]);
  return pairs;
}
}  // namespace

Interface find_interface(const Mesh& mesh, const Partition& p) {
  Interface iface;
  iface.multiplicity.assign(static_cast<size_t>(mesh.num_nodes()), 0);
  const auto ns = node_subdomains(mesh, p);
  for (size_t i = 0; i < ns.size();) {
    size_t j = i;
    InterfaceNode n;
    n.node = ns[i].first;
    while (j < ns.size() && ns[j].first == n.node) n.subdomains.push_back(ns[j++].second);
    iface.multiplicity[n.node] = static_cast<int>(n.subdomains.size());
    if (n.subdomains.size() > 1) iface.nodes.push_back(std::move(n));
    i = j;
  }
  size_t at = 0;  // both lists are sorted by node
  for (const auto& [node, pair] : facet_pairs(mesh, p)) {
    while (at + 1 < iface.nodes.size() && iface.nodes[at].node < node) ++at;
    iface.nodes[at].face_pairs.push_back(pair);
  }
  return iface;
}

std::vector<std::pair<int, int>> constraint_pairs(const InterfaceNode& n, Multipliers choice) {
  if (choice == Multipliers::NonRedundant) return tree_pairs(n, false);
  if (choice == Multipliers::FacePairs) return tree_pairs(n, true);
  std::vector<std::pair<int, int>> pairs;
  for (size_t i = 0; i < n.subdomains.size(); ++i)
    for (size_t j = i + 1; j < n.subdomains.size(); ++j) pairs.emplace_back(n.subdomains[i], n.subdomains[j]);
  return pairs;
}

long count_multipliers(const Interface& iface, const DofMap& body_dofs, Multipliers choice) {
  long count = 0;
  for (const InterfaceNode& n : iface.nodes) {
    long free = 0;
    for (int c = 0; c < body_dofs.dim(); ++c) free += body_dofs.equation(n.node, c) >= 0 ? 1 : 0;
    count += free * static_cast<long>(constraint_pairs(n, choice).size());
  }
  return count;
}

long paper_convention_count(const Interface& iface, int dim) {
  const Multipliers paper = dim == 2 ? Multipliers::NonRedundant : Multipliers::FacePairs;
  long count = 0;
  for (const InterfaceNode& n : iface.nodes) count += dim * static_cast<long>(constraint_pairs(n, paper).size());
  return count;
}

std::vector<SparseMatrix> boolean_blocks(const Interface& iface, const DofMap& body_dofs,
                                         const std::vector<Subdomain>& subs, Multipliers choice) {
  using Triplet = Eigen::Triplet<double, int>;
  std::vector<std::vector<Triplet>> entries(subs.size());
  int row = 0;
  for (const InterfaceNode& n : iface.nodes)
    for (const auto& [a, b] : constraint_pairs(n, choice))
      for (int c = 0; c < body_dofs.dim(); ++c) {
        if (body_dofs.equation(n.node, c) < 0) continue;  // prescribed: eliminated in every subdomain
        entries[a].emplace_back(row, subs[a].local_equation(n.node, c), 1.0);
        entries[b].emplace_back(row, subs[b].local_equation(n.node, c), -1.0);
        ++row;
      }
  std::vector<SparseMatrix> B(subs.size());
  for (size_t s = 0; s < subs.size(); ++s) {
    B[s].resize(row, subs[s].dofs->num_free());
    B[s].setFromTriplets(entries[s].begin(), entries[s].end());
  }
  return B;
}

}  // namespace rollsim
