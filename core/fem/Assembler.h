#pragma once
// Assembly of one group's stiffness and internal force over its free dofs. The sparsity pattern and the
// element -> value-slot scatter map are computed once; assemble() only rewrites values.
#include <algorithm>
#include <vector>

#include "base/SparseMatrix.h"
#include "fem/ElementGeometryCache.h"
#include "fem/FiniteStrainElement.h"
#include "model/DofMap.h"
#include "model/Model.h"

namespace rollsim {

/// The integration-point state of a group's elements (element-major, Gauss point by Gauss point, state_size()
/// values each): the state committed at the last converged increment and the trial state of the current iterate.
struct IntegrationState {
  int per_element = 0;  // Gauss points × the material's state_size()
  std::vector<double> committed, trial;
  double dt = 0;  // the time from the committed to the trial state [s] (0: quasi-static, no time)

  /// The state of every element of `body` (empty for a material without state): zero, but for the equivalent plastic
  /// strain and the temperature rise a body starts from (Body::initial_plastic_strain, initial_temperature), or the
  /// whole state it is given (Body::initial_state).
  static IntegrationState initial(const Body& body);
  void commit() { committed = trial; }
};

class Assembler {
 public:
  Assembler(const Body& body, const DofMap& dofs);

  /// K_ff (both triangles stored) and the internal force on the free dofs, f_int = Σ_e f_e(u_e), at the
  /// displacement `u` of every node (node-major, prescribed dofs included). The element kernel is small-strain
  /// and linear today (f_e = K_e u_e); the finite-strain kernel takes its place with the same signature.
  void assemble(const Eigen::VectorXd& u, SparseMatrix& K, Eigen::VectorXd& f_int) const;
  /// The Newton kernel: f_int from the material's update at every integration point (from `state.committed`,
  /// writing `state.trial`) and, when K is not null, the consistent tangent K_ff. With `v` (every node's dofs),
  /// f_int is predicted at u + v by the tangent at u: f_int(u) + K(u) v — the step's prescribed-displacement
  /// increment enters the first Newton iteration this way. Returns the first inverted element, or -1.
  /// `memo`: what a finite-strain body's assembly does with its points' material updates
  /// (FiniteStrainElement::PointUpdates).
  int assemble(const Eigen::VectorXd& u, SparseMatrix* K, Eigen::VectorXd& f_int, IntegrationState& state,
               const Eigen::VectorXd* v = nullptr, PointMemo memo = PointMemo::off) const;
  /// K_ff and the load of the prescribed dofs at u_f = 0, f_D = −K_fp u_p: the linear system K_ff u_f = f + f_D.
  void assemble(SparseMatrix& K, Eigen::VectorXd& f_dirichlet) const;
  /// Adds a matrix in element e's dofs (node-major, column-major storage) to K_ff, which has this pattern: a load's
  /// stiffness on one of the element's facets.
  void add_element_matrix(int e, const Eigen::MatrixXd& Ke, SparseMatrix& K) const;
  /// Threads for the Newton kernel's elements (computed concurrently, added in element order: the result does not
  /// depend on the count).
  void set_threads(int threads) { threads_ = std::max(1, threads); }

 private:
  const Body& body_;
  const DofMap& dofs_;
  std::vector<int> outer_, inner_;  // K_ff's pattern, compressed columns (values are not kept: a zero matrix is
                                    // written where it is assembled, 9 MB fewer for a 32 x 16 x 8 block)
  /// K := K_ff's pattern, all values zero.
  void zero_matrix(SparseMatrix& K) const;
  /// Element e's equations into eq and the value index of each (i, j) of its matrix (or -1) into s.
  void element_slots(int e, int* eq, int* s) const;
  /// Element e's row of the scatter map, the map built on first use (a Newton run assembles many times).
  const int* slots(int e) const;
  mutable std::vector<int> slot_;  // per element, per (i, j) of the element matrix: value index or -1
  int threads_ = 1;
  // the finite-strain kernel's reference gradients, kept between assemblies (one of the two, by the mesh's dim)
  mutable ElementGeometryCache<2> geometry2_;
  mutable ElementGeometryCache<3> geometry3_;
  mutable std::vector<FiniteStrainElement<2>::PointUpdates> memo2_;  // per element, once a PointMemo::keep asked
  mutable std::vector<FiniteStrainElement<3>::PointUpdates> memo3_;
};

/// A nodal field at every integration point, Σ N_a v_a, element-major (`nodal`: one value per node of `mesh`).
std::vector<double> point_values(const Mesh& mesh, const double* nodal);

/// Each integration point's temperature rise over the body's material temperature from its initial nodal
/// temperatures (Σ N_a T_a − T), element-major; empty without Body::initial_temperature.
std::vector<double> initial_point_rises(const Body& body);

/// Element dof -> equation (or -1) for element e, node-major.
void element_equations(const Mesh& mesh, const DofMap& dofs, int e, int* eq);

}  // namespace rollsim
