#include "partition/Decomposition.h"

#include "fem/Loads.h"
#include "partition/PartitionCheck.h"

namespace rollsim {

long BodyDecomposition::num_rigid_modes() const {
  long n = 0;
  for (const Group& g : groups) n += g.R.cols();
  return n;
}

namespace {
bool ids_in_range(const Mesh& mesh, const Partition& p) {
  if (p.element_subdomain.size() != static_cast<size_t>(mesh.num_elements())) return false;
  for (int s : p.element_subdomain)
    if (s < 0 || s >= p.num_subdomains) return false;
  return true;
}

void validate(const Body& body, int b, Partition& p, bool split, std::vector<std::string>& warnings) {
  const std::string path = "bodies[" + std::to_string(b) + "].partition";
  if (split && ids_in_range(body.mesh, p))
    for (std::string& w : split_disconnected(body.mesh, p)) warnings.push_back(path + ": " + w);
  const std::vector<PartitionProblem> problems = check_partition(body.mesh, p, path);
  if (!problems.empty()) throw PartitionError(problems);
}
}  // namespace

BodyDecomposition decompose_body(const Model& model, int b, Partition partition, const DecomposeOptions& options) {
  const Body& body = model.bodies[b];
  const DofMap dofs(body, b, model.displacements);
  return decompose_body(body, b, dofs, external_nodal_load(model, b), std::move(partition), options);
}

BodyDecomposition decompose_body(const Body& body, int b, const DofMap& dofs, const Eigen::VectorXd& nodal_load,
                                 Partition partition, const DecomposeOptions& options) {
  BodyDecomposition dec;
  dec.body = b;
  dec.body_free_dofs = dofs.num_free();
  dec.multipliers = options.multipliers;
  validate(body, b, partition, options.split_disconnected, dec.warnings);
  dec.partition = std::move(partition);
  dec.subdomains = extract_subdomains(body, dofs, dec.partition);
  dec.interface = find_interface(body.mesh, dec.partition);
  dec.paper_convention_multipliers = paper_convention_count(dec.interface, body.mesh.dim);
  std::vector<SparseMatrix> B = boolean_blocks(dec.interface, dofs, dec.subdomains, options.multipliers);
  for (size_t s = 0; s < dec.subdomains.size(); ++s) {
    dec.groups.push_back(
        subdomain_group(dec.subdomains[s], b, body.name, nodal_load, dec.interface.multiplicity, options.assemble));
    dec.groups.back().C = std::move(B[s]);
  }
  dec.d = Eigen::VectorXd::Zero(dec.groups.empty() ? 0 : dec.groups.front().C.rows());
  return dec;
}

Eigen::VectorXd gather_free(const BodyDecomposition& dec, const std::vector<Eigen::VectorXd>& u, InterfaceValue how) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(dec.body_free_dofs), count = sum;
  for (size_t s = 0; s < dec.subdomains.size(); ++s) {
    const std::vector<int>& map = dec.subdomains[s].free_dofs;
    for (size_t l = 0; l < map.size(); ++l) {
      if (how == InterfaceValue::FirstCopy && count[map[l]] > 0) continue;
      sum[map[l]] += u[s][static_cast<Eigen::Index>(l)];
      count[map[l]] += 1;
    }
  }
  for (Eigen::Index i = 0; i < sum.size(); ++i)
    if (count[i] > 0) sum[i] /= count[i];
  return sum;
}

std::vector<SparseMatrix> split_constraint_columns(const SparseMatrix& C_body, const BodyDecomposition& dec) {
  using Triplet = Eigen::Triplet<double, int>;
  std::vector<std::pair<int, int>> owner(static_cast<size_t>(dec.body_free_dofs), {-1, -1});  // (subdomain, local)
  for (size_t s = dec.subdomains.size(); s-- > 0;)  // the lowest subdomain writes last and wins
    for (size_t l = 0; l < dec.subdomains[s].free_dofs.size(); ++l)
      owner[dec.subdomains[s].free_dofs[l]] = {static_cast<int>(s), static_cast<int>(l)};
  std::vector<std::vector<Triplet>> entries(dec.subdomains.size());
  for (int j = 0; j < C_body.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(C_body, j); it; ++it)
      entries[owner[j].first].emplace_back(it.row(), owner[j].second, it.value());
  std::vector<SparseMatrix> C(dec.subdomains.size());
  for (size_t s = 0; s < C.size(); ++s) {
    C[s].resize(C_body.rows(), dec.subdomains[s].dofs->num_free());
    C[s].setFromTriplets(entries[s].begin(), entries[s].end());
  }
  return C;
}

void append_to_system(BlockSystem& sys, BodyDecomposition& dec) {
  using Triplet = Eigen::Triplet<double, int>;
  const Eigen::Index m0 = sys.d.size(), m = m0 + dec.d.size();
  for (Group& g : sys.groups) {
    const Eigen::Index cols = g.C.cols() > 0 ? g.C.cols() : g.K.rows();
    g.C.conservativeResize(m, cols);
  }
  for (Group& g : dec.groups) {
    std::vector<Triplet> entries;
    for (int j = 0; j < g.C.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(g.C, j); it; ++it)
        entries.emplace_back(static_cast<int>(m0 + it.row()), j, it.value());
    SparseMatrix shifted(m, g.C.cols());
    shifted.setFromTriplets(entries.begin(), entries.end());
    g.C = std::move(shifted);
    sys.groups.push_back(std::move(g));
  }
  sys.d.conservativeResize(m);
  sys.d.tail(dec.d.size()) = dec.d;
  dec.groups.clear();
}

}  // namespace rollsim
