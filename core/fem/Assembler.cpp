#include "fem/Assembler.h"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>

#include "base/Parallel.h"
#include "fem/ElementLoop.h"
#include "fem/FiniteStrainElement.h"

namespace rollsim {

void element_equations(const Mesh& mesh, const DofMap& dofs, int e, int* eq) {
  const int* conn = mesh.element(e);
  const int d = mesh.dim;
  for (int a = 0; a < mesh.nodes_per_elem(); ++a)
    for (int c = 0; c < d; ++c) eq[a * d + c] = dofs.equation(conn[a], c);
}

namespace {
/// Sorted neighbour lists of the node graph (nodes sharing an element, itself included).
std::vector<std::vector<int>> node_adjacency(const Mesh& m) {
  std::vector<std::vector<int>> adj(static_cast<size_t>(m.num_nodes()));
  const int nn = m.nodes_per_elem();
  for (int e = 0; e < m.num_elements(); ++e)
    for (int a = 0; a < nn; ++a)
      for (int b = 0; b < nn; ++b) adj[m.element(e)[a]].push_back(m.element(e)[b]);
  for (auto& list : adj) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return adj;
}
}  // namespace

Assembler::Assembler(const Body& body, const DofMap& dofs) : body_(body), dofs_(dofs) {
  const Mesh& m = body.mesh;
  const int d = m.dim, n = dofs.num_free();
  // pattern from the node graph: equations are node-major, so rows come out sorted
  const auto adj = node_adjacency(m);
  outer_.assign(static_cast<size_t>(n) + 1, 0);
  for (int node = 0; node < m.num_nodes(); ++node)
    for (int c = 0; c < d; ++c) {
      const int j = dofs.equation(node, c);
      if (j < 0) continue;
      for (int other : adj[node])
        for (int k = 0; k < d; ++k)
          if (dofs.equation(other, k) >= 0) inner_.push_back(dofs.equation(other, k));
      outer_[static_cast<size_t>(j) + 1] = static_cast<int>(inner_.size());
    }
}

void Assembler::zero_matrix(SparseMatrix& K) const {
  const auto n = static_cast<Eigen::Index>(outer_.size() - 1);
  K.resize(n, n);
  K.resizeNonZeros(static_cast<Eigen::Index>(inner_.size()));
  std::copy(outer_.begin(), outer_.end(), K.outerIndexPtr());
  std::copy(inner_.begin(), inner_.end(), K.innerIndexPtr());
  std::fill(K.valuePtr(), K.valuePtr() + inner_.size(), 0.0);
}

void Assembler::element_slots(int e, int* eq, int* s) const {
  const Mesh& m = body_.mesh;
  const int d = m.dim, nd = m.nodes_per_elem() * d;
  const int* outer = outer_.data();
  const int* rows = inner_.data();
  element_equations(m, dofs_, e, eq);
  // a node's free dofs are consecutive equations, so consecutive in every column holding them: one search per node
  // of the element and column, the node's other dofs following it (checked; searched where they do not). A node's
  // columns share one pattern: a column after the node's first free one takes that column's slots, shifted.
  for (int jj = 0; jj < nd; ++jj) {
    const int j = eq[jj];
    if (j > 0 && jj % d != 0 && eq[jj - 1] == j - 1) {
      const int shift = outer[j] - outer[j - 1];
      for (int ii = 0; ii < nd; ++ii) {
        const int prev = s[(jj - 1) * nd + ii];
        s[jj * nd + ii] = prev < 0 ? -1 : prev + shift;
      }
      continue;
    }
    const int *begin = rows + (j < 0 ? 0 : outer[j]), *end = rows + (j < 0 ? 0 : outer[j + 1]);
    const int* at = begin;  // where the last node's dofs were found
    for (int ii = 0; ii < nd; ++ii) {
      const int i = eq[ii];
      if (i < 0 || j < 0) {
        s[jj * nd + ii] = -1;
        continue;
      }
      if (ii % d == 0 || at + 1 >= end || at[1] != i) {
        at = std::lower_bound(begin, end, i);
      } else {
        ++at;
      }
      s[jj * nd + ii] = static_cast<int>(at - rows);
    }
  }
}

const int* Assembler::slots(int e) const {
  const Mesh& m = body_.mesh;
  const int nd = m.nodes_per_elem() * m.dim;
  if (slot_.empty() && m.num_elements() > 0) {  // the scatter map, built when a second assembly may need it
    std::vector<int> eq(static_cast<size_t>(nd));
    slot_.resize(static_cast<size_t>(m.num_elements()) * nd * nd);
    for (int k = 0; k < m.num_elements(); ++k)
      element_slots(k, eq.data(), slot_.data() + static_cast<size_t>(k) * nd * nd);
  }
  return slot_.data() + static_cast<size_t>(e) * nd * nd;
}

void Assembler::assemble(const Eigen::VectorXd& u, SparseMatrix& K, Eigen::VectorXd& f_int) const {
  const Mesh& m = body_.mesh;
  const int nd = m.nodes_per_elem() * m.dim;
  zero_matrix(K);
  f_int = Eigen::VectorXd::Zero(dofs_.num_free());
  double* val = K.valuePtr();
  std::vector<int> eq(static_cast<size_t>(nd)), own(static_cast<size_t>(nd) * nd);
  std::vector<double> ue(static_cast<size_t>(nd));
  for_each_element_stiffness(body_, [&](int e, const double* Ke) {
    // a linear system is assembled once: its element's slots found here, not kept (9 MB for a 32 x 16 x 8 block)
    element_slots(e, eq.data(), own.data());
    const int* s = own.data();
    const int* conn = m.element(e);
    for (int jj = 0; jj < nd; ++jj) ue[jj] = u[static_cast<Eigen::Index>(conn[jj / m.dim]) * m.dim + jj % m.dim];
    for (int jj = 0; jj < nd; ++jj) {
      if (ue[jj] != 0.0)  // f_e = K_e u_e, column by column (an element at rest costs nothing)
        for (int ii = 0; ii < nd; ++ii)
          if (eq[ii] >= 0) f_int[eq[ii]] += Ke[jj * nd + ii] * ue[jj];
      if (eq[jj] < 0) continue;
      for (int ii = 0; ii < nd; ++ii)
        if (s[jj * nd + ii] >= 0) val[s[jj * nd + ii]] += Ke[jj * nd + ii];
    }
  });
}

IntegrationState IntegrationState::initial(const Body& body) {
  IntegrationState s;
  const int points = body.mesh.dim == 2 ? SolidElement<2>::NGP : SolidElement<3>::NGP;
  s.per_element = points * make_material(body.material)->state_size();
  s.committed.assign(static_cast<size_t>(s.per_element) * body.mesh.num_elements(), 0.0);
  if (!body.initial_state.empty()) {
    if (body.initial_state.size() != s.committed.size())
      throw std::invalid_argument("body '" + body.name + "': an initial state of " +
                                  std::to_string(body.initial_state.size()) + " values for points holding " +
                                  std::to_string(s.committed.size()));
    s.committed = s.trial = body.initial_state;
    return s;
  }
  const auto material = make_material(body.material);
  const int size = material->state_size(), alpha = material->equivalent_plastic_strain_index();
  const int rise = body.material.thermal() ? material->temperature_rise_index() : -1;
  const std::vector<double> rises = initial_point_rises(body);
  for (size_t p = 0; size > 0 && p < s.committed.size() / static_cast<size_t>(size); ++p) {
    if (alpha >= 0 && !body.initial_plastic_strain.empty())
      s.committed[p * size + alpha] = body.initial_plastic_strain[p / static_cast<size_t>(points)];
    if (rise >= 0 && !rises.empty()) s.committed[p * size + rise] = rises[p];
  }
  s.trial = s.committed;
  return s;
}

std::vector<double> point_values(const Mesh& m, const double* nodal) {
  std::vector<double> out;
  const auto add = [&](const auto& N) {
    for (int e = 0; e < m.num_elements(); ++e)
      for (int p = 0; p < N.rows(); ++p) {
        double v = 0;
        for (int a = 0; a < N.cols(); ++a) v += N(p, a) * nodal[m.element(e)[a]];
        out.push_back(v);
      }
  };
  if (m.dim == 2)
    add(SolidElement<2>::gauss_shape());
  else
    add(SolidElement<3>::gauss_shape());
  return out;
}

std::vector<double> initial_point_rises(const Body& body) {
  if (body.initial_temperature.empty()) return {};
  std::vector<double> rises = point_values(body.mesh, body.initial_temperature.data());
  for (double& r : rises) r -= body.material.temperature;
  return rises;
}

namespace {
/// Element results computed together before they are added in element order: the sums, and so the result, are
/// those of one thread whatever the thread count (a chunk: ~1 ms of 2D kernels, ~8 ms of 3D ones, 2.3 MB of 3D
/// matrices).
constexpr int kChunk = 512;

template <int D>
struct NewtonKernel {
  using El = SolidElement<D>;
  const Body& body;
  const Material& material;
  const Eigen::VectorXd& u;
  const Eigen::VectorXd* v;
  bool tangent;
  IntegrationState& state;
  ElementGeometryCache<D>& geometry;
  std::vector<typename FiniteStrainElement<D>::PointUpdates>* memo;  // null: PointMemo::off
  PointMemo memo_mode;

  /// Element e's force (predicted along v when its nodes move) and, when asked, its tangent; false: inverted.
  bool operator()(int e, typename El::Stiffness& Ke, typename El::Dofs& fe) const {
    const Mesh& m = body.mesh;
    const int* conn = m.element(e);
    typename El::Dofs ue, ve;
    for (int a = 0; a < El::NN; ++a)
      for (int i = 0; i < D; ++i) {
        const Eigen::Index k = static_cast<Eigen::Index>(conn[a]) * D + i;
        ue(a * D + i) = u[k];
        ve(a * D + i) = v ? (*v)[k] : 0.0;
      }
    const bool moved = v && !ve.isZero(0.0);
    const size_t at = static_cast<size_t>(e) * state.per_element;
    const double* c = state.per_element ? state.committed.data() + at : nullptr;
    double* t = state.per_element ? state.trial.data() + at : nullptr;
    typename El::Stiffness* K = tangent || moved ? &Ke : nullptr;
    const bool finite = body.kinematics == Kinematics::Finite;
    bool ok;
    if (finite) {
      typename El::Geometry scratch;
      const typename El::Geometry* reference = geometry.at(e, element_coords<D>(m, e), scratch);
      auto* kept = memo ? &(*memo)[static_cast<size_t>(e)] : nullptr;
      ok = reference && FiniteStrainElement<D>::tangent_and_force(*reference, material, body.formulation, ue, c, t, K,
                                                                  fe, nullptr, kept, memo_mode);
    } else {
      ok = El::tangent_and_force(element_coords<D>(m, e), material, body.formulation, ue, c, t, K, fe);
    }
    if (!ok) return false;
    if (K && finite) Ke = 0.5 * (Ke + Ke.transpose()).eval();  // CHOLMOD: symmetric
    if (moved) fe.noalias() += Ke * ve;
    return true;
  }
};

template <int D>
int newton_elements(const NewtonKernel<D>& kernel, int threads,
                    const std::function<void(int, const double*, const double*)>& scatter) {
  using El = SolidElement<D>;
  const int n = kernel.body.mesh.num_elements();
  std::vector<typename El::Stiffness> Ke(static_cast<size_t>(std::min(n, kChunk)));
  std::vector<typename El::Dofs> fe(Ke.size());
  std::vector<char> ok(Ke.size());
  for (int begin = 0; begin < n; begin += kChunk) {
    const int count = std::min(kChunk, n - begin);
    // contiguous runs of elements, not one element per hand-out: a shared counter bumped per 2D element (~2 µs of
    // work) and neighbouring flags written from both threads cost what the second thread gained
    const int runs = std::min(count, 16), per_run = (count + runs - 1) / runs;
    for_each_group(static_cast<size_t>(runs), threads, [&](size_t r) {
      for (int i = static_cast<int>(r) * per_run; i < std::min(count, (static_cast<int>(r) + 1) * per_run); ++i)
        ok[i] = kernel(begin + i, Ke[i], fe[i]);
    });
    for (int i = 0; i < count; ++i) {
      if (!ok[i]) return begin + i;
      scatter(begin + i, kernel.tangent ? Ke[i].data() : nullptr, fe[i].data());
    }
  }
  return -1;
}

/// The element records a PointMemo uses (sized to the body's elements; null when off).
template <class Records>
Records* memo_of(Records& records, PointMemo memo, int elements) {
  if (memo == PointMemo::off || static_cast<size_t>(elements) * sizeof(records[0]) > kElementCacheBytes) return nullptr;
  if (records.size() != static_cast<size_t>(elements)) {
    records.clear();
    records.resize(static_cast<size_t>(elements));  // none valid
  }
  return &records;
}
}  // namespace

int Assembler::assemble(const Eigen::VectorXd& u, SparseMatrix* K, Eigen::VectorXd& f_int, IntegrationState& state,
                        const Eigen::VectorXd* v, PointMemo memo) const {
  const Mesh& m = body_.mesh;
  const int nd = m.nodes_per_elem() * m.dim;
  if (K) zero_matrix(*K);
  f_int = Eigen::VectorXd::Zero(dofs_.num_free());
  double* val = K ? K->valuePtr() : nullptr;
  std::vector<int> eq(static_cast<size_t>(nd));
  auto scatter = [&](int e, const double* Ke, const double* fe) {
    element_equations(m, dofs_, e, eq.data());
    for (int ii = 0; ii < nd; ++ii)
      if (eq[ii] >= 0) f_int[eq[ii]] += fe[ii];
    if (!Ke) return;
    const int* s = slots(e);
    for (int k = 0; k < nd * nd; ++k)
      if (s[k] >= 0) val[s[k]] += Ke[k];
  };
  const auto material = make_material(body_.material, state.dt);
  if (m.dim == 2) {
    geometry2_.resize(m.num_elements());
    return newton_elements<2>(
        {body_, *material, u, v, K != nullptr, state, geometry2_, memo_of(memo2_, memo, m.num_elements()), memo},
        threads_, scatter);
  }
  geometry3_.resize(m.num_elements());
  return newton_elements<3>(
      {body_, *material, u, v, K != nullptr, state, geometry3_, memo_of(memo3_, memo, m.num_elements()), memo},
      threads_, scatter);
}

void Assembler::add_element_matrix(int e, const Eigen::MatrixXd& Ke, SparseMatrix& K) const {
  const int nd = body_.mesh.nodes_per_elem() * body_.mesh.dim;
  const int* s = slots(e);
  double* val = K.valuePtr();
  for (int k = 0; k < nd * nd; ++k)
    if (s[k] >= 0) val[s[k]] += Ke.data()[k];
}

void Assembler::assemble(SparseMatrix& K, Eigen::VectorXd& f_dirichlet) const {
  assemble(dofs_.expand(Eigen::VectorXd::Zero(dofs_.num_free())), K, f_dirichlet);
  f_dirichlet = -f_dirichlet;
}

}  // namespace rollsim
