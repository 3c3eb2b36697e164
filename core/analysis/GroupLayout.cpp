#include "analysis/GroupLayout.h"

#include <algorithm>
#include <tuple>

#include "fem/Loads.h"
#include "model/RigidModes.h"

namespace rollsim {

namespace {
bool in_contact(const Model& model, int b) {
  for (const ContactPair& p : model.contacts)
    if (p.slave_body == b || p.master_body == b) return true;
  return false;
}

/// One group for a whole body and, for a body held only by contact, its kernel (paper eq. (5)).
Group body_group(const Model& model, int b, const DofMap& dofs) {
  const Body& body = model.bodies[b];
  Group g;
  g.name = body.name;
  g.body = b;
  g.R = in_contact(model, b) ? kernel_basis(body.mesh, dofs) : Eigen::MatrixXd(dofs.num_free(), 0);
  return g;
}

/// Each free dof's node coordinates and component, and the rigid modes there in `frame` (Group::geometry).
DofGeometry dof_geometry(const Mesh& mesh, const DofMap& dofs, const ModeFrame& frame) {
  DofGeometry g;
  g.x.resize(dofs.num_free(), mesh.dim);
  g.component.resize(dofs.num_free());
  for (int n = 0; n < mesh.num_nodes(); ++n)
    for (int c = 0; c < mesh.dim; ++c)
      if (const int e = dofs.equation(n, c); e >= 0) {
        for (int k = 0; k < mesh.dim; ++k) g.x(e, k) = mesh.nodes[n][k];
        g.component[e] = c;
      }
  g.modes = rigid_mode_rows(g.x, g.component, frame);
  return g;
}

/// Multiplicity scaling of the interface rows, in boolean_blocks' order (node, pair, free component).
std::vector<double> row_scaling(const BodyDecomposition& dec, const DofMap& dofs) {
  std::vector<double> w;
  for (const InterfaceNode& n : dec.interface.nodes)
    for (size_t p = 0; p < constraint_pairs(n, dec.multipliers).size(); ++p)
      for (int c = 0; c < dofs.dim(); ++c)
        if (dofs.equation(n.node, c) >= 0) w.push_back(1.0 / dec.interface.multiplicity[n.node]);
  return w;
}

SparseMatrix shift_rows(const SparseMatrix& A, long offset, long rows) {
  std::vector<Eigen::Triplet<double, int>> t;
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      t.emplace_back(static_cast<int>(offset + it.row()), j, it.value());
  SparseMatrix S(static_cast<int>(rows), A.cols());
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

/// [top; bottom] for two blocks with the same columns.
SparseMatrix stack(const SparseMatrix& top, const SparseMatrix& bottom) {
  SparseMatrix S = shift_rows(bottom, top.rows(), top.rows() + bottom.rows());
  return S + shift_rows(top, 0, S.rows());
}
}  // namespace

GroupLayout::GroupLayout(const Model& model, bool split, Multipliers choice) {
  redundant_ = choice != Multipliers::NonRedundant;
  for (size_t b = 0; b < model.bodies.size(); ++b) add_body(model, static_cast<int>(b), split, choice);
  // interface rows of every body, one after the other
  std::vector<long> offset;
  for (const BodyGroups& bg : bodies_) {
    offset.push_back(interface_rows_);
    if (bg.dec) interface_rows_ += bg.dec->num_multipliers();
  }
  interface_C_.resize(sys_.groups.size());
  for (size_t b = 0; b < bodies_.size(); ++b)
    for (int i = 0; i < bodies_[b].count; ++i) {
      const int g = bodies_[b].first + i;
      const SparseMatrix& B = sys_.groups[g].C;
      interface_C_[g] = bodies_[b].dec ? shift_rows(B, offset[b], interface_rows_)
                                       : SparseMatrix(static_cast<int>(interface_rows_), free_dofs(g));
    }
  set_contact(BodyConstraints{});
}

void GroupLayout::add_body(const Model& model, int b, bool split, Multipliers choice) {
  const Body& body = model.bodies[b];
  dofs_.push_back(std::make_unique<DofMap>(body, b, model.displacements));
  BodyGroups bg;
  bg.first = static_cast<int>(sys_.groups.size());
  if (dofs_.back()->num_free() == 0) {  // a body moved wholly by its conditions (a rigid roll): nothing to solve
    bg.count = 0;
  } else if (split && body.partition.num_subdomains > 1) {
    DecomposeOptions opt;
    opt.multipliers = choice;
    opt.assemble = false;
    const Eigen::VectorXd load = external_nodal_load(model, b);
    bg.dec = decompose_body(body, b, *dofs_.back(), load, body.partition, opt);
    const std::vector<FollowerPressure> follower = follower_pressures(model, b);
    for (const Subdomain& s : bg.dec->subdomains) {
      GroupSource source = subdomain_source(s, b, load, bg.dec->interface.multiplicity);
      source.follower = subdomain_follower(s, follower);
      assembler_.add(std::move(source));
    }
    warnings_.insert(warnings_.end(), bg.dec->warnings.begin(), bg.dec->warnings.end());
    paper_rows_ += bg.dec->paper_convention_multipliers;
    const auto w = row_scaling(*bg.dec, *dofs_.back());
    interface_scaling_.insert(interface_scaling_.end(), w.begin(), w.end());
    bg.count = static_cast<int>(bg.dec->groups.size());
    for (Group& g : bg.dec->groups) sys_.groups.push_back(std::move(g));
    bg.dec->groups.clear();
  } else {
    sys_.groups.push_back(body_group(model, b, *dofs_.back()));
    assembler_.add(
        GroupSource{&body, dofs_.back().get(), external_nodal_load(model, b), b, {}, follower_pressures(model, b)});
  }
  const ModeFrame frame = mode_frame(body.mesh);  // the whole body's: its subdomains' modes agree where they meet
  for (size_t g = static_cast<size_t>(bg.first); g < sys_.groups.size(); ++g)
    sys_.groups[g].geometry = dof_geometry(assembler_.source(g).body->mesh, *assembler_.source(g).dofs, frame);
  bodies_.push_back(std::move(bg));
}

void GroupLayout::add_body_load(const std::vector<Eigen::VectorXd>& load, const std::vector<size_t>& groups) {
  std::vector<char> listed(sys_.groups.size(), 0);
  for (size_t g : groups) listed[g] = 1;
  for (size_t b = 0; b < bodies_.size(); ++b) {
    const BodyGroups& bg = bodies_[b];
    if (bg.count == 0) continue;
    if (!bg.dec) {
      if (listed[bg.first]) sys_.groups[bg.first].f += load[b];
      continue;
    }
    const SparseMatrix row = SparseMatrix(Eigen::MatrixXd(load[b].transpose()).sparseView());
    const std::vector<SparseMatrix> parts = split_constraint_columns(row, *bg.dec);
    for (int i = 0; i < bg.count; ++i)
      if (listed[bg.first + i]) sys_.groups[bg.first + i].f += Eigen::VectorXd(parts[i].transpose());
  }
}

std::pair<int, int> GroupLayout::group_equation(int body, int node, int comp, int within) const {
  const BodyGroups& bg = bodies_[body];
  if (bg.count == 0) return {-1, -1};
  if (!bg.dec) return {bg.first, dofs_[body]->equation(node, comp)};
  for (int i = within < 0 ? 0 : within; i < (within < 0 ? bg.count : within + 1); ++i)
    if (const int e = bg.dec->subdomains[i].local_equation(node, comp); e >= 0) return {bg.first + i, e};
  return {-1, -1};
}

long GroupLayout::add_body_stiffness(const std::vector<StiffnessEntry>& entries, const std::vector<size_t>& groups,
                                     SparseMatrix* cross) {
  std::vector<char> listed(sys_.groups.size(), 0);
  for (size_t g : groups) listed[g] = 1;
  std::vector<long> offset(sys_.groups.size() + 1, 0);
  for (size_t g = 0; g < sys_.groups.size(); ++g) offset[g + 1] = offset[g] + free_dofs(g);
  std::vector<Eigen::Triplet<double, int>> between;
  long dropped = 0;
  for (const StiffnessEntry& e : entries) {
    auto [gi, ei] = group_equation(e.body_i, e.node_i, e.comp_i);
    auto [gj, ej] = group_equation(e.body_j, e.node_j, e.comp_j);
    if (gi < 0 || ei < 0 || gj < 0 || ej < 0) continue;  // a prescribed dof: its increment is known
    if (e.body_i == e.body_j && bodies_[e.body_i].dec)   // a torn body: a subdomain holding both dofs
      for (int s = 0; s < bodies_[e.body_i].count && gi != gj; ++s) {
        const auto a = group_equation(e.body_i, e.node_i, e.comp_i, s),
                   b = group_equation(e.body_j, e.node_j, e.comp_j, s);
        if (a.second >= 0 && b.second >= 0) std::tie(gi, ei, gj, ej) = std::tie(a.first, a.second, b.first, b.second);
      }
    if (gi != gj) {
      if (cross)
        between.emplace_back(static_cast<int>(offset[gi] + ei), static_cast<int>(offset[gj] + ej), e.value);
      else
        ++dropped;
      continue;
    }
    if (!listed[gi]) continue;
    SparseMatrix& K = sys_.groups[gi].K;
    const auto begin = K.innerIndexPtr() + K.outerIndexPtr()[ej], end = K.innerIndexPtr() + K.outerIndexPtr()[ej + 1];
    const auto at = std::lower_bound(begin, end, ei);
    if (at == end || *at != ei) {
      ++dropped;
      continue;
    }
    K.valuePtr()[at - K.innerIndexPtr()] += e.value;
  }
  if (cross) {
    *cross = SparseMatrix(static_cast<int>(offset.back()), static_cast<int>(offset.back()));
    cross->setFromTriplets(between.begin(), between.end());
  }
  return dropped;
}

void GroupLayout::set_contact(const BodyConstraints& contact) {
  const long mc = contact.d.size();
  for (size_t b = 0; b < bodies_.size(); ++b) {
    const BodyGroups& bg = bodies_[b];
    std::vector<SparseMatrix> parts;
    if (contact.C.empty())
      for (int i = 0; i < bg.count; ++i) parts.emplace_back(0, free_dofs(bg.first + i));
    else if (bg.dec)
      parts = split_constraint_columns(contact.C[b], *bg.dec);
    else
      parts = {contact.C[b]};
    for (int i = 0; i < bg.count; ++i) sys_.groups[bg.first + i].C = stack(parts[i], interface_C_[bg.first + i]);
    std::vector<SparseMatrix> eq;  // C + the coupling of slipping friction: the multipliers' block in the equations
    if (!contact.coupling.empty()) {
      const SparseMatrix Ce = contact.C[b] + contact.coupling[b];
      eq = bg.dec ? split_constraint_columns(Ce, *bg.dec) : std::vector<SparseMatrix>{Ce};
    }
    for (int i = 0; i < bg.count; ++i)
      sys_.groups[bg.first + i].C_eq = eq.empty() ? SparseMatrix() : stack(eq[i], interface_C_[bg.first + i]);
  }
  sys_.d = Eigen::VectorXd::Zero(mc + interface_rows_);
  sys_.d.head(mc) = contact.d;
  ConstraintBlock glue{ConstraintKind::Glue, mc, mc + interface_rows_, Eigen::VectorXd(interface_rows_),
                       redundant_,           {}};
  for (long r = 0; r < interface_rows_; ++r) glue.scaling[r] = interface_scaling_[r];
  sys_.blocks = {ConstraintBlock{ConstraintKind::Contact, 0, mc, {}, false, contact.slave_body}, std::move(glue)};
}

bool GroupLayout::set_compliant(const std::vector<ConstraintRow>& rows, const std::vector<double>& stiffness) {
  for (const ConstraintRow& row : rows)
    for (const ConstraintTerm& term : row.terms)
      if (bodies_[term.body].dec) return false;
  std::vector<std::vector<Eigen::Triplet<double, int>>> t(sys_.groups.size());
  std::vector<double> compliance;
  for (size_t r = 0; r < rows.size(); ++r) {
    const int at = static_cast<int>(compliance.size());
    bool any = false;
    for (const ConstraintTerm& term : rows[r].terms) {
      const auto [g, eq] = group_equation(term.body, term.node, term.comp);
      if (g < 0 || eq < 0) continue;  // a prescribed dof: it does not move within the iteration
      t[g].emplace_back(at, eq, term.coef);
      any = true;
    }
    if (any) compliance.push_back(1.0 / stiffness[r]);
  }
  const int m = static_cast<int>(compliance.size());
  for (size_t g = 0; g < sys_.groups.size(); ++g) {
    sys_.groups[g].C_compliant = SparseMatrix(m, free_dofs(g));
    sys_.groups[g].C_compliant.setFromTriplets(t[g].begin(), t[g].end());
  }
  sys_.compliance = m ? Eigen::VectorXd(Eigen::Map<Eigen::VectorXd>(compliance.data(), m)) : Eigen::VectorXd();
  return true;
}

void GroupLayout::move_nodes(int b, const std::vector<std::array<double, 3>>& nodes) {
  std::optional<BodyDecomposition>& dec = bodies_[static_cast<size_t>(b)].dec;
  if (!dec) return;
  for (Subdomain& s : dec->subdomains)
    for (size_t l = 0; l < s.nodes.size(); ++l) s.body.mesh.nodes[l] = nodes[static_cast<size_t>(s.nodes[l])];
}

std::vector<Eigen::VectorXd> GroupLayout::body_solution(const BlockSolution& sol) const {
  std::vector<Eigen::VectorXd> u;
  for (const BodyGroups& bg : bodies_) {
    if (bg.count == 0) {
      u.emplace_back(0);
      continue;
    }
    if (!bg.dec) {
      u.push_back(sol.u[bg.first]);
      continue;
    }
    const std::vector<Eigen::VectorXd> parts(sol.u.begin() + bg.first, sol.u.begin() + bg.first + bg.count);
    u.push_back(gather_free(*bg.dec, parts));
  }
  return u;
}

}  // namespace rollsim
