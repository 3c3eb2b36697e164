#include "solve/InterfaceFlexibility.h"

#include <algorithm>

namespace rollsim {

namespace {
/// Columns solved together: enough for level-3 speed, few enough that the n × kChunk blocks stay small.
constexpr Eigen::Index kChunk = 512;
/// A new factor's Φ = WᵀW takes W = L⁻¹PE (n × columns) whole: up to this many entries (512 MiB), then chunks of
/// full solves (twice the triangular work).
constexpr double kWholeQuadratic = 64.0 * 1024 * 1024;
}  // namespace

Eigen::MatrixXd InterfaceFlexibility::interface_block(const Group& g, GroupSolver& solver) {
  const Eigen::Index n = g.K.rows();
  std::vector<int> dofs = touched_dofs(g.C);
  const SparseMatrix& Ceq = g.equation_C();
  if (&Ceq != &g.C) {
    const std::vector<int> more = touched_dofs(Ceq);
    std::vector<int> all;
    std::set_union(dofs.begin(), dofs.end(), more.begin(), more.end(), std::back_inserter(all));
    dofs = std::move(all);
  }
  // a new factor, or Φ grown to several times what the constraints touch now (the arc moved far on): start again
  if (version_ != g.version || static_cast<Eigen::Index>(position_.size()) != n ||
      dofs_.size() > 4 * dofs.size() + 64) {
    version_ = g.version;
    dofs_.clear();
    position_.assign(static_cast<size_t>(n), -1);
    phi_.resize(0, 0);
  }
  extend(dofs, solver);
  const SparseMatrix C = on_held_dofs(g.C), CeqT = SparseMatrix(on_held_dofs(Ceq).transpose());
  const Eigen::MatrixXd CPhi = C * phi_;
  return Eigen::MatrixXd(CPhi * CeqT);
}

void InterfaceFlexibility::extend(const std::vector<int>& dofs, GroupSolver& solver) {
  std::vector<int> fresh;
  for (int d : dofs)
    if (position_[static_cast<size_t>(d)] < 0) fresh.push_back(d);
  if (fresh.empty()) return;
  const auto old = static_cast<Eigen::Index>(dofs_.size());
  const auto grown = old + static_cast<Eigen::Index>(fresh.size());
  for (int d : fresh) {
    position_[static_cast<size_t>(d)] = static_cast<int>(dofs_.size());
    dofs_.push_back(d);
  }
  if (old == 0 && static_cast<double>(grown) * static_cast<double>(position_.size()) <= kWholeQuadratic) {
    // a new factor: Φ in one block, Eᵀ K⁺ E
    phi_ = solver.inverse_block(dofs_, dofs_);
    solved_ += grown;
    return;
  }
  phi_.conservativeResize(grown, grown);
  for (Eigen::Index first = 0; first < static_cast<Eigen::Index>(fresh.size()); first += kChunk) {
    const Eigen::Index count = std::min<Eigen::Index>(kChunk, static_cast<Eigen::Index>(fresh.size()) - first);
    const std::vector<int> cols(fresh.begin() + first, fresh.begin() + first + count);
    phi_.middleCols(old + first, count) = solver.inverse_block(dofs_, cols);  // every held row, the fresh columns
    // K⁺ is symmetric (the assembler keeps a symmetric tangent): the old rows' new columns are the new rows' old ones
    phi_.block(old + first, 0, count, old) = phi_.block(0, old + first, old, count).transpose();
    solved_ += count;
  }
}

SparseMatrix InterfaceFlexibility::on_held_dofs(const SparseMatrix& C) const {
  std::vector<Eigen::Triplet<double, int>> t;
  t.reserve(static_cast<size_t>(C.nonZeros()));
  for (int j = 0; j < C.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(C, j); it; ++it)
      t.emplace_back(it.row(), position_[static_cast<size_t>(j)], it.value());
  SparseMatrix out(C.rows(), static_cast<int>(dofs_.size()));
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

}  // namespace rollsim
