#include "analysis/GroupAssembler.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "fem/Assembler.h"
#include "model/RigidModes.h"

namespace rollsim {

void GroupAssembler::add(GroupSource source) {
  states_.push_back(IntegrationState::initial(*source.body));
  evaluations_.push_back(0);
  memo_ready_.push_back(0);
  sources_.push_back(std::move(source));
}

void GroupAssembler::assemble(const std::vector<size_t>& groups, const std::vector<Eigen::VectorXd>& u_free,
                              double load_factor, BlockSystem& sys) const {
  if (sys.groups.size() != sources_.size())
    throw std::logic_error("GroupAssembler: the system has " + std::to_string(sys.groups.size()) +
                           " groups, the assembler knows " + std::to_string(sources_.size()));
  for (size_t g : groups) {
    const GroupSource& src = sources_[g];
    const bool at_rest = g >= u_free.size() || u_free[g].size() == 0;
    const Eigen::VectorXd u =
        src.dofs->expand(at_rest ? Eigen::VectorXd::Zero(src.dofs->num_free()) : u_free[g], load_factor);
    Group& group = sys.groups[g];
    Eigen::VectorXd f_int;
    assembler(g).assemble(u, group.K, f_int);
    group.f = src.dofs->restrict_to_free(load_factor * src.nodal_load) - f_int;
    add_follower_pressures(g, u, load_factor, group.f, nullptr);
    ++evaluations_[g];
  }
}

InvertedElement GroupAssembler::assemble_newton(const std::vector<size_t>& which, const std::vector<size_t>& tangent,
                                                const std::vector<Eigen::VectorXd>& u_free, Factors at,
                                                BlockSystem& sys) {
  std::vector<char> with_tangent(sources_.size(), 0);
  for (size_t g : tangent) with_tangent[g] = 1;
  auto assembled_here = [&](size_t g) { return with_tangent[g] && (local_.empty() || local_[g]); };
  for (size_t g : which) {
    const GroupSource& src = sources_[g];
    const Eigen::VectorXd u = src.dofs->expand(u_free[g], at.prescribed);
    Eigen::VectorXd v;
    if (at.prescribed_step != 0.0) {  // the prescribed dofs' motion over the step (free dofs: zero)
      const Eigen::VectorXd zero = Eigen::VectorXd::Zero(u_free[g].size());
      v = src.dofs->expand(zero, at.prescribed + at.prescribed_step) - src.dofs->expand(zero, at.prescribed);
    }
    Group& group = sys.groups[g];
    Eigen::VectorXd f_int;
    // a tangent after this group's residual at the same iterate (the selective update's second pass) takes the
    // points' updates the residual kept
    const PointMemo memo = with_tangent[g] && memo_ready_[g] ? PointMemo::reuse : PointMemo::keep;
    memo_ready_[g] = 0;
    const int bad = assembler(g).assemble(u, assembled_here(g) ? &group.K : nullptr, f_int, states_[g],
                                          v.size() ? &v : nullptr, memo);
    if (bad >= 0) return InvertedElement{static_cast<int>(g), bad};
    memo_ready_[g] = 1;
    group.f = src.dofs->restrict_to_free(at.load * src.nodal_load) - f_int;
    add_follower_pressures(g, u, at.load, group.f, assembled_here(g) ? &group.K : nullptr);
    if (with_tangent[g] && group.R.cols() && src.body->kinematics == Kinematics::Finite)
      follow_kernel(group, src, u, assembled_here(g));
    evaluations_[g] += with_tangent[g];
  }
  return {};
}

void GroupAssembler::add_follower_pressures(size_t g, const Eigen::VectorXd& u, double factor, Eigen::VectorXd& f,
                                            SparseMatrix* K) const {
  const GroupSource& src = sources_[g];
  if (src.follower.empty()) return;
  const Mesh& mesh = src.body->mesh;
  f += src.dofs->restrict_to_free(factor * follower_nodal_load(mesh, src.follower, u));
  if (!K) return;
  for (const FollowerPressure& p : src.follower)
    for (const Facet& facet : p.facets) {
      const Eigen::MatrixXd dF = follower_facet_stiffness(mesh, facet, p.value, u);
      assembler(g).add_element_matrix(facet.element, -0.5 * factor * (dF + dF.transpose()), *K);
    }
}

const Assembler& GroupAssembler::assembler(size_t g) const {
  if (assemblers_.size() < sources_.size()) assemblers_.resize(sources_.size());
  if (!assemblers_[g]) assemblers_[g] = std::make_unique<Assembler>(*sources_[g].body, *sources_[g].dofs);
  assemblers_[g]->set_threads(threads_);
  return *assemblers_[g];
}

void GroupAssembler::set_local(const std::vector<size_t>& groups) {
  local_.assign(sources_.size(), 0);
  for (size_t g : groups) local_.at(g) = 1;
}

void GroupAssembler::follow_kernel(Group& group, const GroupSource& src, const Eigen::VectorXd& u, bool tangent_here) {
  Eigen::MatrixXd R = kernel_basis(src.body->mesh, *src.dofs, &u);  // the geometric modes, turned with the body
  if (R.cols() < group.R.cols()) return;
  group.R = tangent_here ? stiffness_kernel(group.K, R) : std::move(R);  // a stressed body: translations only
}

void GroupAssembler::commit() {
  for (IntegrationState& s : states_) s.commit();
  forget_point_updates();
}

std::vector<double> GroupAssembler::committed_state(int body, int elements) const {
  std::vector<double> all;
  for (size_t g = 0; g < sources_.size(); ++g) {
    const GroupSource& src = sources_[g];
    const IntegrationState& st = states_[g];
    if (src.model_body != body || st.per_element == 0) continue;
    if (src.body_elements.empty()) return st.committed;
    const size_t per = static_cast<size_t>(st.per_element);
    all.resize(per * static_cast<size_t>(elements), 0.0);
    for (size_t e = 0; e < src.body_elements.size(); ++e)
      std::copy_n(st.committed.begin() + static_cast<std::ptrdiff_t>(per * e), per,
                  all.begin() + static_cast<std::ptrdiff_t>(per * static_cast<size_t>(src.body_elements[e])));
  }
  return all;
}

void GroupAssembler::set_committed_state(int body, const std::vector<double>& all) {
  for (size_t g = 0; g < sources_.size(); ++g) {
    const GroupSource& src = sources_[g];
    IntegrationState& st = states_[g];
    if (src.model_body != body || st.per_element == 0) continue;
    memo_ready_[g] = 0;
    if (src.body_elements.empty()) {
      st.committed = all;
    } else {
      const size_t per = static_cast<size_t>(st.per_element);
      for (size_t e = 0; e < src.body_elements.size(); ++e)
        std::copy_n(all.begin() + static_cast<std::ptrdiff_t>(per * static_cast<size_t>(src.body_elements[e])), per,
                    st.committed.begin() + static_cast<std::ptrdiff_t>(per * e));
    }
    st.trial = st.committed;
  }
}

std::vector<size_t> all_groups(const BlockSystem& sys) {
  std::vector<size_t> all(sys.groups.size());
  std::iota(all.begin(), all.end(), size_t{0});
  return all;
}

}  // namespace rollsim
