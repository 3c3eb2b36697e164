#include "analysis/DriverSteps.h"

#include <Eigen/Eigenvalues>

namespace rollsim {

namespace {
// Names the body, node and component of global equation `col` (groups stacked in order), and what the factorization
// found (`what`).
std::string describe_singular(const Model& model, const std::vector<std::unique_ptr<DofMap>>& dofs, int col,
                              const std::string& what) {
  std::string where;
  int offset = 0;
  for (size_t b = 0; b < dofs.size() && where.empty(); ++b) {
    const DofMap& d = *dofs[b];
    if (col >= offset && col < offset + d.num_free()) {
      const Mesh& m = model.bodies[b].mesh;
      for (int n = 0; n < m.num_nodes() && where.empty(); ++n)
        for (int c = 0; c < m.dim; ++c)
          if (d.equation(n, c) == col - offset) {
            const auto& x = m.nodes[n];
            where = " at body '" + model.bodies[b].name + "', node " + std::to_string(n) + " (" + std::to_string(x[0]) +
                    ", " + std::to_string(x[1]) + (m.dim == 3 ? ", " + std::to_string(x[2]) : "") + "), component " +
                    "xyz"[c];
          }
    }
    offset += d.num_free();
  }
  return "the stiffness matrix is singular" + where + " (to working precision: " + what +
         "): a body or part of it is not held against rigid-body motion (add displacement or symmetry conditions), "
         "or its material is nearly incompressible (Poisson's ratio close to 0.5 needs the B-bar formulation) or "
         "its stiffnesses differ by more than 1e12";
}
}  // namespace

double load_factor(int i, int n) { return i == n ? 1.0 : static_cast<double>(i) / n; }

BlockSolution solve_checked(const Model& model, const std::vector<std::unique_ptr<DofMap>>& dofs,
                            SolverStrategy& solver, const BlockSystem& sys, AnalysisObserver& obs) {
  try {
    return solver.solve(sys, &obs);
  } catch (const SingularMatrix& e) {
    if (sys.num_rigid_modes() > 0)
      throw AnalysisError("the system is singular: the contact constraints do not hold the floating bodies (" +
                          std::to_string(sys.num_rigid_modes()) + " rigid modes; " + e.what() +
                          ") — check that the contact surfaces meet and hold every free direction");
    const bool one_body_per_group = sys.groups.size() == model.bodies.size();
    throw AnalysisError(describe_singular(model, dofs, one_body_per_group ? e.column : -1, e.what()));
  } catch (const std::invalid_argument& e) {
    throw AnalysisError(e.what());
  }
}

std::vector<Eigen::VectorXd> full_displacements(const std::vector<std::unique_ptr<DofMap>>& dofs,
                                                const std::vector<Eigen::VectorXd>& free, double load_factor) {
  std::vector<Eigen::VectorXd> u;
  for (size_t b = 0; b < dofs.size(); ++b) u.push_back(dofs[b]->expand(free[b], load_factor));
  return u;
}

bool has_unilateral(const Model& model) {
  for (const ContactPair& p : model.contacts)
    if (p.kind != ContactKind::Tied) return true;
  return false;
}

/// Every rigid mode of a floating group must move some constrained dof: G = [C_g R_g] of full column rank (paper
/// eq. (8) is solvable only then). Checked for every strategy, so that none returns an answer for a body that
/// nothing holds (a frictionless contact cannot hold sideways motion, for one).
void check_floating_groups_held(const BlockSystem& sys) {
  const long k = sys.num_rigid_modes();
  if (k == 0) return;
  // G = [C_g R_g] is sparse (a group's modes touch only its own constraint rows): GᵀG from the sparse G costs
  // O(nnz) where the dense product cost m k² (and a Jacobi SVD of GᵀG k³ with a large constant) — on 2D 120×120
  // in 10×10 subdomains (k = 269) that check took longer than the FETI solve it guards.
  std::vector<Eigen::Triplet<double, int>> t;
  std::vector<std::string> owner;
  for (const Group& g : sys.groups)
    if (g.R.cols()) {
      const Eigen::MatrixXd CR = g.C * g.R;
      const int first = static_cast<int>(owner.size());
      for (int j = 0; j < CR.cols(); ++j)
        for (int i = 0; i < CR.rows(); ++i)
          if (CR(i, j) != 0.0) t.emplace_back(i, first + j, CR(i, j));
      owner.insert(owner.end(), static_cast<size_t>(g.R.cols()), g.name);
    }
  SparseMatrix G(static_cast<int>(sys.num_multipliers()), static_cast<int>(k));
  G.setFromTriplets(t.begin(), t.end());
  const Eigen::MatrixXd GtG = Eigen::MatrixXd(SparseMatrix(G.transpose() * G));
  // GᵀG is symmetric positive semi-definite: its eigenvalues are its singular values
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> values(GtG, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd ev = values.eigenvalues();  // ascending
  if (ev.size() && ev[0] > 1e-10 * std::max(ev[ev.size() - 1], 1e-300)) return;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> vectors(GtG);
  Eigen::Index worst = 0;
  vectors.eigenvectors().col(0).cwiseAbs().maxCoeff(&worst);
  throw AnalysisError(
      "the system is singular: the contact constraints do not hold the floating bodies — a rigid "
      "motion of '" +
      owner[worst] +
      "' moves no constrained dof (check that the contact surfaces "
      "meet and hold every free direction, or add a support)");
}

Multipliers multiplier_choice(const SolverOptions& o) {
  return o.multipliers == GlueMultipliers::Redundant ? Multipliers::FullyRedundant : Multipliers::NonRedundant;
}

}  // namespace rollsim
