#include "partition/Subdomain.h"

#include <algorithm>

namespace rollsim {

int Subdomain::local_node(int body_node) const {
  const auto it = std::lower_bound(nodes.begin(), nodes.end(), body_node);
  return it != nodes.end() && *it == body_node ? static_cast<int>(it - nodes.begin()) : -1;
}

int Subdomain::local_equation(int body_node, int comp) const {
  const int l = local_node(body_node);
  return l < 0 ? -1 : dofs->equation(l, comp);
}

namespace {
Mesh local_mesh(const Mesh& m, const std::vector<int>& elements, const std::vector<int>& nodes) {
  Mesh local;
  local.dim = m.dim;
  local.type = m.type;
  for (int n : nodes) local.nodes.push_back(m.nodes[n]);
  for (int e : elements)
    for (int k = 0; k < m.nodes_per_elem(); ++k) {
      const int n = m.element(e)[k];
      local.connectivity.push_back(static_cast<int>(std::lower_bound(nodes.begin(), nodes.end(), n) - nodes.begin()));
    }
  return local;
}

Subdomain make_subdomain(const Body& body, const DofMap& body_dofs, int id, std::vector<int> elements) {
  Subdomain s;
  s.id = id;
  s.elements = std::move(elements);
  const Mesh& m = body.mesh;
  for (int e : s.elements) s.nodes.insert(s.nodes.end(), m.element(e), m.element(e) + m.nodes_per_elem());
  std::sort(s.nodes.begin(), s.nodes.end());
  s.nodes.erase(std::unique(s.nodes.begin(), s.nodes.end()), s.nodes.end());
  s.body.name = body.name + "/" + std::to_string(id);
  s.body.mesh = local_mesh(m, s.elements, s.nodes);
  s.body.material = body.material;
  s.body.material_name = body.material_name;
  s.body.formulation = body.formulation;
  s.body.kinematics = body.kinematics;  // (finite-strain bodies were solved small-strain under feti before this)
  s.dofs = std::make_unique<DofMap>(body_dofs, s.nodes);
  s.free_dofs.assign(static_cast<size_t>(s.dofs->num_free()), -1);
  for (size_t l = 0; l < s.nodes.size(); ++l)
    for (int c = 0; c < m.dim; ++c) {
      const int eq = s.dofs->equation(static_cast<int>(l), c);
      if (eq >= 0) s.free_dofs[eq] = body_dofs.equation(s.nodes[l], c);
    }
  return s;
}
}  // namespace

std::vector<Subdomain> extract_subdomains(const Body& body, const DofMap& body_dofs, const Partition& p) {
  std::vector<std::vector<int>> elements = subdomain_elements(p);
  std::vector<Subdomain> subs;
  subs.reserve(elements.size());
  for (size_t s = 0; s < elements.size(); ++s)
    subs.push_back(make_subdomain(body, body_dofs, static_cast<int>(s), std::move(elements[s])));
  return subs;
}

}  // namespace rollsim
