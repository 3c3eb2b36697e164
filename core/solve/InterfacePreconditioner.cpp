#include "solve/InterfacePreconditioner.h"

#include <algorithm>
#include <stdexcept>

#include "base/Parallel.h"
#include "solve/CholeskyOrLU.h"
#include "solve/Factorization.h"
#include "solve/SolverStrategy.h"

namespace rollsim {

namespace {
SparseMatrix select(const SparseMatrix& A, const std::vector<int>& rows, const std::vector<int>& cols) {
  std::vector<int> rpos(static_cast<size_t>(A.rows()), -1), cpos(static_cast<size_t>(A.cols()), -1);
  for (size_t i = 0; i < rows.size(); ++i) rpos[rows[i]] = static_cast<int>(i);
  for (size_t i = 0; i < cols.size(); ++i) cpos[cols[i]] = static_cast<int>(i);
  std::vector<Eigen::Triplet<double, int>> t;
  for (int j = 0; j < A.outerSize(); ++j)
    if (cpos[j] >= 0)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it)
        if (rpos[it.row()] >= 0) t.emplace_back(rpos[it.row()], cpos[j], it.value());
  SparseMatrix S(static_cast<int>(rows.size()), static_cast<int>(cols.size()));
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

/// Per group: boundary dofs, C_g on them (scaled by W), K_bb, and for dirichlet K_ib and the factor of K_ii.
struct GroupBlocks {
  std::vector<int> boundary;
  SparseMatrix WCb;   // W C_g restricted to the boundary columns
  SparseMatrix WCbT;  // its transpose, stored: the sparse products of apply_columns need its rows
  SparseMatrix Kbb, Kib;
  std::unique_ptr<Factorization> Kii;
};

class BlockPreconditioner final : public InterfacePreconditioner {
 public:
  BlockPreconditioner(bool dirichlet, int threads, std::shared_ptr<const GroupDistribution> spread)
      : dirichlet_(dirichlet), threads_(threads), spread_(std::move(spread)) {}

  void setup(const BlockSystem& sys) override {
    blocks_.clear();
    Eigen::VectorXd w = sys.row_scaling();
    const ConstraintBlock* glue = sys.glue();
    glue_ = glue ? std::make_pair(glue->begin, glue->size()) : std::make_pair(0L, 0L);
    BBt_.reset();
    if (glue && !glue->redundant) {
      factor_glue(sys);
      w.segment(glue_.first, glue_.second).setOnes();  // (B Bᵀ)⁻¹ replaces the multiplicity weights
    }
    const RowCopies copies = row_copies(sys);
    // independent per group: concurrently on the solver's threads, like the groups' own factorizations
    blocks_.resize(sys.groups.size());
    for_each_group(sys.groups.size(), threads_, [&](size_t i) {
      const Group& g = sys.groups[i];
      GroupBlocks& b = blocks_[i];
      if (spread_ && !spread_->holds(i)) return;  // its holder's (another process's K_g is not assembled here)
      SparseMatrix WC = weights(sys, w, copies, g.body).asDiagonal() * g.C;
      WC.prune(0.0);
      b.boundary = touched_dofs(WC);
      if (!b.boundary.empty()) {
        std::vector<int> all(static_cast<size_t>(g.C.rows()));
        for (size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
        b.WCb = select(WC, all, b.boundary);
        b.WCbT = b.WCb.transpose();
        b.Kbb = select(g.K, b.boundary, b.boundary);
        if (dirichlet_) factor_interior(g, b);
      }
    });
  }

  SparseMatrix apply_columns(const BlockSystem&, const SparseMatrix& X) const override {
    if (spread_)
      throw std::invalid_argument(
          "the mixed method over MPI does not spread the preconditioner-weighted projector: solver.projector must be "
          "identity");
    const SparseMatrix Xs = scale_columns(X);
    std::vector<std::vector<Eigen::Triplet<double, int>>> parts(blocks_.size());
    for_each_group(blocks_.size(), threads_, [&](size_t i) {
      const GroupBlocks& b = blocks_[i];
      if (b.boundary.empty()) return;
      const SparseMatrix V = b.WCbT * Xs;  // boundary dofs × columns, most columns empty
      for (int j = 0; j < V.outerSize(); ++j) {
        if (V.outerIndexPtr()[j + 1] == V.outerIndexPtr()[j]) continue;
        const Eigen::VectorXd sv = schur(b, Eigen::VectorXd(V.col(j)));
        for (int k = 0; k < b.WCb.outerSize(); ++k)  // W C_b (S v), entry by entry (summed by setFromTriplets)
          for (SparseMatrix::InnerIterator it(b.WCb, k); it; ++it)
            parts[i].emplace_back(it.row(), j, it.value() * sv[k]);
      }
    });
    std::vector<Eigen::Triplet<double, int>> all;  // in group order: the sums do not depend on the threads
    for (const auto& p : parts) all.insert(all.end(), p.begin(), p.end());
    SparseMatrix Z(X.rows(), X.cols());
    Z.setFromTriplets(all.begin(), all.end());
    return scale_columns(Z);
  }

  Eigen::VectorXd apply(const BlockSystem&, const Eigen::VectorXd& r_in) const override {
    const Eigen::VectorXd r = scale(r_in);
    // the local products (and the K_ii solves) concurrently, their sum in group order: the same for any threads
    std::vector<Eigen::VectorXd> s(blocks_.size());
    for_each_group(blocks_.size(), threads_, [&](size_t i) {
      const GroupBlocks& b = blocks_[i];
      if (b.boundary.empty()) return;
      s[i] = schur(b, b.WCb.transpose() * r);
    });
    Eigen::VectorXd z = Eigen::VectorXd::Zero(r.size());
    for (size_t i = 0; i < blocks_.size(); ++i)
      if (!blocks_[i].boundary.empty()) z += blocks_[i].WCb * s[i];
    if (spread_) spread_->sum(z);  // the other processes' groups
    return scale(z);
  }

 private:
  /// Per contact row: how many groups of the body that preconditions it touch it, and how many of the others — the
  /// copies of a node that subdomains share, each holding 1/k of the row's coefficient (split_constraint_columns).
  struct RowCopies {
    Eigen::VectorXd own, other;
  };
  static RowCopies row_copies(const BlockSystem& sys) {
    RowCopies k{Eigen::VectorXd::Zero(sys.num_multipliers()), Eigen::VectorXd::Zero(sys.num_multipliers())};
    for (const Group& g : sys.groups) {
      std::vector<char> touched(static_cast<size_t>(g.C.rows()), 0);
      for (int j = 0; j < g.C.outerSize(); ++j)
        for (SparseMatrix::InnerIterator it(g.C, j); it; ++it) touched[static_cast<size_t>(it.row())] = 1;
      for (const ConstraintBlock& c : sys.blocks)
        if (c.kind == ConstraintKind::Contact && static_cast<long>(c.preconditioned_by.size()) == c.size())
          for (long r = 0; r < c.size(); ++r)
            if (touched[static_cast<size_t>(c.begin + r)])
              (c.preconditioned_by[static_cast<size_t>(r)] == g.body ? k.own : k.other)[c.begin + r] += 1;
    }
    return k;
  }

  /// The rows' weights for the groups of `body`. On a contact row: its slave side's groups in full, the other side's
  /// at a tenth (kOtherSideWeight), each times the number of its groups the row touches. A node-to-segment row's
  /// multiplier acts on its slave node: the slave side's Schur complement is what preconditions it, as a mortar
  /// method's non-mortar side does. With the master's added in full, the roll's swamped the slab's in the gap and
  /// the rolling pass's interface iterations grew with the slab's subdomains (docs/BENCHMARKS-PETSC.md, "Where the
  /// growth comes from"); left out entirely, the preconditioner lost the rank a floating slave subdomain's singular
  /// Schur complement does not give, and CG broke down on the 3D pass. A node that k subdomains share holds 1/k of
  /// the row on each copy: k² (1/k)² Σ S_copy is the node's stiffness in all of them, as for a node in one.
  static Eigen::VectorXd weights(const BlockSystem& sys, const Eigen::VectorXd& w, const RowCopies& copies, int body) {
    Eigen::VectorXd out = w;
    for (const ConstraintBlock& c : sys.blocks)
      if (c.kind == ConstraintKind::Contact && static_cast<long>(c.preconditioned_by.size()) == c.size())
        for (long r = c.begin; r < c.end; ++r) {
          const bool own = c.preconditioned_by[static_cast<size_t>(r - c.begin)] == body;
          out[r] *= own ? std::max(1.0, copies.own[r]) : kOtherSideWeight * std::max(1.0, copies.other[r]);
        }
    return out;
  }
  static constexpr double kOtherSideWeight = 0.1;

  /// S v = K_bb v − K_bi K_ii⁻¹ K_ib v (dirichlet), K_bb v (lumped)
  static Eigen::VectorXd schur(const GroupBlocks& b, const Eigen::VectorXd& v) {
    Eigen::VectorXd s = b.Kbb * v;
    if (b.Kii) s -= b.Kib.transpose() * b.Kii->solve(b.Kib * v);
    return s;
  }

  static void factor_interior(const Group& g, GroupBlocks& b) {
    std::vector<char> is_boundary(static_cast<size_t>(g.K.rows()), 0);
    for (int d : b.boundary) is_boundary[d] = 1;
    std::vector<int> interior;
    for (int d = 0; d < g.K.rows(); ++d)
      if (!is_boundary[d]) interior.push_back(d);
    if (interior.empty()) return;
    b.Kib = select(g.K, interior, b.boundary);
    const SparseMatrix Kii = select(g.K, interior, interior);
    b.Kii = std::make_unique<CholeskyOrLU>();  // an indefinite K_ii (a body's tangent past a limit point) goes to LU
    b.Kii->analyze(Kii);
    b.Kii->factorize(Kii);
  }

  /// Non-redundant glue (a spanning tree of k − 1 pairs where k subdomains meet) is scaled by (B Bᵀ)⁻¹, the
  /// generalisation of the 1/2 weights of a two-subdomain interface: with plain 1/k weights the crosspoints spoil
  /// the preconditioner (measured: Dirichlet 34 iterations instead of 8 on a 20×20 cantilever, 4×2 subdomains).
  void factor_glue(const BlockSystem& sys) {
    SparseMatrix BBt(static_cast<int>(glue_.second), static_cast<int>(glue_.second));
    for (const Group& g : sys.groups) {
      const SparseMatrix B = g.C.middleRows(glue_.first, glue_.second);
      BBt += SparseMatrix(B * B.transpose());
    }
    BBt_ = make_factorization("cholmod");
    BBt_->analyze(BBt);
    BBt_->factorize(BBt);
  }
  Eigen::VectorXd scale(const Eigen::VectorXd& v) const {
    if (!BBt_) return v;
    Eigen::VectorXd out = v;
    out.segment(glue_.first, glue_.second) = BBt_->solve(v.segment(glue_.first, glue_.second));
    return out;
  }
  /// scale() column by column, kept sparse: B Bᵀ couples only the multipliers of one interface dof, so a
  /// column's support does not grow (the solve leaves exact zeros outside it)
  SparseMatrix scale_columns(const SparseMatrix& X) const {
    if (!BBt_) return X;
    std::vector<Eigen::Triplet<double, int>> t;
    for (int j = 0; j < X.outerSize(); ++j) {
      if (X.outerIndexPtr()[j + 1] == X.outerIndexPtr()[j]) continue;
      const Eigen::VectorXd c = scale(Eigen::VectorXd(X.col(j)));
      for (int r = 0; r < c.size(); ++r)
        if (c[r] != 0.0) t.emplace_back(r, j, c[r]);
    }
    SparseMatrix Y(X.rows(), X.cols());
    Y.setFromTriplets(t.begin(), t.end());
    return Y;
  }

  bool dirichlet_;
  int threads_;
  std::shared_ptr<const GroupDistribution> spread_;
  std::vector<GroupBlocks> blocks_;
  std::pair<long, long> glue_{0, 0};  // first row, count
  std::unique_ptr<Factorization> BBt_;
};
}  // namespace

std::unique_ptr<InterfacePreconditioner> make_interface_preconditioner(
    Preconditioner kind, int threads, std::shared_ptr<const GroupDistribution> spread) {
  if (kind == Preconditioner::None) return nullptr;
  return std::make_unique<BlockPreconditioner>(kind == Preconditioner::Dirichlet, threads, std::move(spread));
}

}  // namespace rollsim
