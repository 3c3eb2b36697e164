#include "partition/PartitionReport.h"

#include <cholmod.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "base/Parallel.h"
#include "model/RigidModes.h"
#include "partition/DualGraph.h"
#include "partition/Interface.h"
#include "partition/PartitionCheck.h"

namespace rollsim {

namespace {
// ============================================================================ factor estimate

/// Compressed rows: row r holds items[start[r] .. start[r + 1]).
struct Csr {
  std::vector<int> start{0}, items;
  const int* begin(int r) const { return items.data() + start[r]; }
  const int* end(int r) const { return items.data() + start[r + 1]; }
};

/// The elements of every node.
Csr node_elements(const Mesh& m) {
  Csr c;
  c.start.assign(static_cast<size_t>(m.num_nodes()) + 1, 0);
  for (int n : m.connectivity) ++c.start[n + 1];
  std::partial_sum(c.start.begin(), c.start.end(), c.start.begin());
  c.items.resize(m.connectivity.size());
  std::vector<int> at(c.start.begin(), c.start.end() - 1);
  for (int e = 0; e < m.num_elements(); ++e)
    for (int k = 0; k < m.nodes_per_elem(); ++k) c.items[at[m.element(e)[k]]++] = e;
  return c;
}

int free_components(const DofMap& dofs, int node) {
  int free = 0;
  for (int c = 0; c < dofs.dim(); ++c) free += dofs.equation(node, c) >= 0 ? 1 : 0;
  return free;
}

/// Nodes with a free dof (weight: how many), joined when they share an element.
struct NodeGraph {
  std::vector<int> node, weight;
  Csr adjacency;  // both directions, no self loops
};

NodeGraph node_graph(const Mesh& m, const DofMap& dofs) {
  NodeGraph g;
  std::vector<int> vertex(static_cast<size_t>(m.num_nodes()), -1);
  for (int n = 0; n < m.num_nodes(); ++n)
    if (const int w = free_components(dofs, n); w > 0) {
      vertex[n] = static_cast<int>(g.node.size());
      g.node.push_back(n);
      g.weight.push_back(w);
    }
  const Csr elements = node_elements(m);
  g.adjacency.start.reserve(g.node.size() + 1);
  g.adjacency.items.reserve(g.node.size() * (m.dim == 2 ? 8 : 26));  // a structured mesh's interior node
  std::vector<int> mark(g.node.size(), -1);
  for (int v = 0; v < static_cast<int>(g.node.size()); ++v) {
    mark[v] = v;
    for (const int* e = elements.begin(g.node[v]); e != elements.end(g.node[v]); ++e)
      for (int k = 0; k < m.nodes_per_elem(); ++k)
        if (const int u = vertex[m.element(*e)[k]]; u >= 0 && mark[u] != v) {
          mark[u] = v;
          g.adjacency.items.push_back(u);
        }
    g.adjacency.start.push_back(static_cast<int>(g.adjacency.items.size()));
  }
  return g;
}

/// AMD (through CHOLMOD) on the node graph: perm[k] = the vertex eliminated k-th.
std::vector<int> amd_order(const NodeGraph& g) {
  std::vector<int> perm(g.node.size());
  if (perm.empty()) return perm;
  cholmod_sparse a{};
  a.nrow = a.ncol = perm.size();
  a.nzmax = g.adjacency.items.size();
  a.p = const_cast<int*>(g.adjacency.start.data());
  a.i = const_cast<int*>(g.adjacency.items.data());
  a.stype = 1;  // symmetric: the upper triangle is read
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_PATTERN;
  a.dtype = CHOLMOD_DOUBLE;
  a.packed = 1;
  cholmod_common common;
  cholmod_start(&common);
  common.print = 0;
  common.error_handler = nullptr;
  const int ok = cholmod_amd(&a, nullptr, 0, perm.data(), &common);
  cholmod_finish(&common);
  if (!ok) throw std::runtime_error("AMD ordering of the node graph failed");
  return perm;
}

/// The graph in elimination order: vertex k = perm[k], neighbours renumbered.
struct Ordered {
  std::vector<int> weight;
  Csr adjacency;
};

Ordered reorder(const NodeGraph& g, const std::vector<int>& perm) {
  std::vector<int> pinv(perm.size());
  for (size_t k = 0; k < perm.size(); ++k) pinv[perm[k]] = static_cast<int>(k);
  Ordered o;
  o.adjacency.items.reserve(g.adjacency.items.size());
  for (int v : perm) {
    o.weight.push_back(g.weight[v]);
    for (const int* u = g.adjacency.begin(v); u != g.adjacency.end(v); ++u) o.adjacency.items.push_back(pinv[*u]);
    o.adjacency.start.push_back(static_cast<int>(o.adjacency.items.size()));
  }
  return o;
}

/// Elimination tree (Liu 1986): parent[k] > k, or -1 for a root.
std::vector<int> elimination_tree(const Csr& adj) {
  const int n = static_cast<int>(adj.start.size()) - 1;
  std::vector<int> parent(static_cast<size_t>(n), -1), ancestor(static_cast<size_t>(n), -1);
  for (int k = 0; k < n; ++k)
    for (const int* p = adj.begin(k); p != adj.end(k); ++p)
      for (int i = *p, next = 0; i != -1 && i < k; i = next) {
        next = ancestor[i];
        ancestor[i] = k;  // path compression
        if (next == -1) parent[i] = k;
      }
  return parent;
}

std::vector<int> postorder(const std::vector<int>& parent) {
  const int n = static_cast<int>(parent.size());
  std::vector<int> head(parent.size(), -1), next(parent.size(), -1), post, stack;
  post.reserve(parent.size());
  for (int j = n - 1; j >= 0; --j)
    if (parent[j] != -1) {
      next[j] = head[parent[j]];
      head[parent[j]] = j;
    }
  for (int root = 0; root < n; ++root) {
    if (parent[root] != -1) continue;
    stack.push_back(root);
    while (!stack.empty()) {
      const int p = stack.back(), child = head[p];
      if (child == -1) {
        stack.pop_back();
        post.push_back(p);
      } else {
        head[p] = next[child];
        stack.push_back(child);
      }
    }
  }
  return post;
}

int find_root(std::vector<int>& ancestor, int i) {
  int root = i;
  while (root != ancestor[root]) root = ancestor[root];
  while (i != root) i = std::exchange(ancestor[i], root);
  return root;
}

/// Per column j of L: Σ w_i over its rows i (diagonal included). Gilbert, Ng & Peyton (1994): row i of L is the
/// subtree of the etree spanned by the leaves j < i with A(i, j) ≠ 0; +w_i at each leaf, −w_i at the least common
/// ancestor of consecutive leaves (postorder) and at parent(i), summed over subtrees.
std::vector<long long> weighted_column_counts(const Ordered& o, const std::vector<int>& parent) {
  const std::vector<int> post = postorder(parent);
  const size_t n = parent.size();
  std::vector<int> first(n, -1), maxfirst(n, -1), prevleaf(n, -1), ancestor(n);
  std::vector<long long> delta(n, 0);
  for (int k = 0; k < static_cast<int>(n); ++k) {
    const int j = post[k];
    delta[j] = first[j] == -1 ? o.weight[j] : 0;  // an etree leaf: row j is j alone
    for (int r = j; r != -1 && first[r] == -1; r = parent[r]) first[r] = k;
  }
  std::iota(ancestor.begin(), ancestor.end(), 0);
  for (const int j : post) {
    if (parent[j] != -1) delta[parent[j]] -= o.weight[j];
    for (const int* p = o.adjacency.begin(j); p != o.adjacency.end(j); ++p) {
      const int i = *p;
      if (i <= j || first[j] <= maxfirst[i]) continue;  // j is no leaf of row i's subtree
      maxfirst[i] = first[j];
      const int previous = std::exchange(prevleaf[i], j);
      delta[j] += o.weight[i];
      if (previous != -1) delta[find_root(ancestor, previous)] -= o.weight[i];
    }
    if (parent[j] != -1) ancestor[j] = parent[j];
  }
  for (size_t j = 0; j < n; ++j)
    if (parent[j] != -1) delta[parent[j]] += delta[j];
  return delta;
}
}  // namespace

FactorEstimate estimate_factor(const Mesh& mesh, const DofMap& dofs, std::vector<int>* node_order) {
  const NodeGraph g = node_graph(mesh, dofs);
  const std::vector<int> perm = amd_order(g);
  const Ordered o = reorder(g, perm);
  const std::vector<long long> rows = weighted_column_counts(o, elimination_tree(o.adjacency));
  FactorEstimate f;
  for (size_t j = 0; j < rows.size(); ++j)  // node j's dofs: the t-th from its last has (rows below) + t entries
    for (int t = 1; t <= o.weight[j]; ++t) {
      const double c = static_cast<double>(rows[j] - o.weight[j] + t);
      f.nnz += c;
      f.flops += c * c;
    }
  if (node_order) {
    node_order->clear();
    for (int v : perm) node_order->push_back(g.node[v]);
  }
  return f;
}

// ============================================================================ the reporter

double predicted_cost(const FactorEstimate& f, const CostModel& m) {
  return m.factorizations * f.flops + (m.cg_iterations * m.substitutions_per_iteration + 2) * 4 * f.nnz;
}

double one_domain_cost(const FactorEstimate& f) { return f.flops + 4 * f.nnz; }

namespace {

/// The shared facets through every node.
Csr node_facets(int num_nodes, const std::vector<SharedFacet>& facets) {
  Csr c;
  c.start.assign(static_cast<size_t>(num_nodes) + 1, 0);
  for (const SharedFacet& f : facets)
    for (int k = 0; k < f.num_nodes; ++k) ++c.start[f.nodes[k] + 1];
  std::partial_sum(c.start.begin(), c.start.end(), c.start.begin());
  c.items.resize(static_cast<size_t>(c.start.back()));
  std::vector<int> at(c.start.begin(), c.start.end() - 1);
  for (size_t f = 0; f < facets.size(); ++f)
    for (int k = 0; k < facets[f].num_nodes; ++k) c.items[at[facets[f].nodes[k]]++] = static_cast<int>(f);
  return c;
}

/// A subdomain's local body and dof pattern as extract_subdomains builds them (elements and nodes in ascending body
/// order, the body's prescribed components; the prescribed values are not needed for counting). `local` is scratch
/// of one entry per body node, -1 on entry and on return.
struct LocalPart {
  Body body;
  DofMap dofs;
};

LocalPart local_part(const Body& body, const DofMap& dofs, const std::vector<int>& elements, std::vector<int>& local) {
  const Mesh& m = body.mesh;
  Body b;
  b.mesh.dim = m.dim;
  b.mesh.type = m.type;
  for (int e : elements)
    for (int k = 0; k < m.nodes_per_elem(); ++k) local[m.element(e)[k]] = 0;
  std::vector<int> nodes;
  for (int n = 0; n < m.num_nodes(); ++n)
    if (local[n] == 0) {
      local[n] = static_cast<int>(nodes.size());
      nodes.push_back(n);
      b.mesh.nodes.push_back(m.nodes[n]);
    }
  b.mesh.connectivity.reserve(elements.size() * static_cast<size_t>(m.nodes_per_elem()));
  for (int e : elements)
    for (int k = 0; k < m.nodes_per_elem(); ++k) b.mesh.connectivity.push_back(local[m.element(e)[k]]);
  std::vector<DisplacementBC> fixed(static_cast<size_t>(m.dim));  // one condition per prescribed component
  for (int c = 0; c < m.dim; ++c) fixed[c].value[c] = 0.0;
  for (size_t l = 0; l < nodes.size(); ++l) {
    for (int c = 0; c < m.dim; ++c)
      if (dofs.equation(nodes[l], c) < 0) fixed[c].nodes.push_back(static_cast<int>(l));
    local[nodes[l]] = -1;
  }
  DofMap d(b, 0, fixed);
  return {std::move(b), std::move(d)};
}

/// check_partition's problems of a non-empty subdomain s, from its local mesh (the same pieces in the same order as
/// on the body: local elements keep the body's order; the lower ids are empty there and dropped).
std::vector<PartitionProblem> subdomain_problems(const Mesh& local, int s, const std::string& path) {
  Partition p;
  p.num_subdomains = s + 1;
  p.element_subdomain.assign(static_cast<size_t>(local.num_elements()), s);
  const std::string where = path + ".subdomains[" + std::to_string(s) + "]";
  std::vector<PartitionProblem> out;
  for (PartitionProblem& q : check_partition(local, p, path))
    if (q.path == where) out.push_back(std::move(q));
  return out;
}

/// What an interface node ties: the solver's pairs (non-redundant) and the paper's.
struct NodeLinks {
  std::vector<std::pair<int, int>> solver, paper;
};

struct SubdomainCache {
  SubdomainReport report;  // multipliers and cost are filled in when the report is assembled
  std::vector<PartitionProblem> problems;
};

}  // namespace

struct PartitionReporter::State {
  const Body& body;
  const DofMap& dofs;
  ReporterOptions options;
  std::vector<SharedFacet> facets;
  Csr node_elements, node_facets, neighbours;  // node → elements, node → facets, element → facet neighbours
  std::vector<int> free;                       // free components per node
  FactorEstimate one_domain;

  bool primed = false;
  std::vector<int> owner;  // element → subdomain of the last map of the right length; -1: none
  std::vector<NodeLinks> links;
  std::vector<long> multipliers, paper;  // per subdomain: rows of B_i
  long total_multipliers = 0, total_paper = 0;
  std::vector<SubdomainCache> cache;
  PartitionReport report;
  int recomputed = 0;

  State(const Body& b, const DofMap& d, ReporterOptions o);
  void relink(int node);
  void add_links(const NodeLinks& l, int node, long sign);
  std::vector<char> move_elements(const std::vector<int>& ids, int num_subdomains);
  std::vector<std::vector<int>> pieces(int s, const std::vector<int>& elements) const;
  SubdomainCache compute(int s, const std::vector<int>& elements) const;
  void recompute(const std::vector<char>& changed);
  void empty_problems(const std::vector<int>& todo);
  void reset();
  void assemble(std::vector<PartitionProblem> id_problems, bool with_subdomains);
};

PartitionReporter::State::State(const Body& b, const DofMap& d, ReporterOptions o)
    : body(b), dofs(d), options(std::move(o)) {
  const Mesh& m = body.mesh;
  for_each_group(2, options.threads, [&](size_t job) {
    if (job == 0) {
      one_domain = estimate_factor(m, dofs);
      return;
    }
    facets = shared_facets(m);
    node_elements = rollsim::node_elements(m);
    node_facets = rollsim::node_facets(m.num_nodes(), facets);
    DualGraph dual = dual_graph(m.num_elements(), facets);
    neighbours.start = std::move(dual.xadj);
    neighbours.items = std::move(dual.adjncy);
  });
  for (int n = 0; n < m.num_nodes(); ++n) free.push_back(free_components(dofs, n));
  owner.assign(static_cast<size_t>(m.num_elements()), -1);
  links.resize(static_cast<size_t>(m.num_nodes()));
}

void PartitionReporter::State::add_links(const NodeLinks& l, int node, long sign) {
  for (const auto& [a, b] : l.solver) {
    multipliers[a] += sign * free[node];
    multipliers[b] += sign * free[node];
    total_multipliers += sign * free[node];
  }
  const long dim = body.mesh.dim;
  for (const auto& [a, b] : l.paper) {
    paper[a] += sign * dim;
    paper[b] += sign * dim;
    total_paper += sign * dim;
  }
}

void PartitionReporter::State::reset() {
  primed = false;
  std::fill(owner.begin(), owner.end(), -1);
  std::fill(links.begin(), links.end(), NodeLinks{});
  multipliers.clear();
  paper.clear();
  total_multipliers = total_paper = 0;
  cache.clear();
}

/// The pairs of one node from the current owners, as find_interface and constraint_pairs see them.
void PartitionReporter::State::relink(int node) {
  add_links(links[node], node, -1);
  InterfaceNode n;
  n.node = node;
  for (const int* e = node_elements.begin(node); e != node_elements.end(node); ++e)
    if (owner[*e] >= 0) n.subdomains.push_back(owner[*e]);
  std::sort(n.subdomains.begin(), n.subdomains.end());
  n.subdomains.erase(std::unique(n.subdomains.begin(), n.subdomains.end()), n.subdomains.end());
  NodeLinks l;
  if (n.subdomains.size() > 1) {
    for (const int* f = node_facets.begin(node); f != node_facets.end(node); ++f) {
      const int a = owner[facets[*f].a], b = owner[facets[*f].b];
      if (a >= 0 && b >= 0 && a != b) n.face_pairs.emplace_back(std::min(a, b), std::max(a, b));
    }
    std::sort(n.face_pairs.begin(), n.face_pairs.end());
    n.face_pairs.erase(std::unique(n.face_pairs.begin(), n.face_pairs.end()), n.face_pairs.end());
    l.solver = constraint_pairs(n, Multipliers::NonRedundant);
    l.paper = body.mesh.dim == 2 ? l.solver : constraint_pairs(n, Multipliers::FacePairs);
  }
  add_links(l, node, +1);
  links[node] = std::move(l);
}

/// Takes the new owners, re-ties the nodes around every moved element; returns the subdomains whose element sets
/// changed (all on the first call).
std::vector<char> PartitionReporter::State::move_elements(const std::vector<int>& ids, int num_subdomains) {
  const size_t width = std::max(cache.size(), static_cast<size_t>(num_subdomains));
  multipliers.resize(width, 0);
  paper.resize(width, 0);
  std::vector<char> changed(width, static_cast<char>(!primed));
  for (size_t s = cache.size(); s < width; ++s) changed[s] = 1;  // new ids: at least their emptiness is news
  std::vector<int> moved;
  for (size_t e = 0; e < ids.size(); ++e)
    if (!primed || ids[e] != owner[e]) {
      for (int s : {owner[e], ids[e]})
        if (s >= 0) changed[s] = 1;
      owner[e] = ids[e];
      moved.push_back(static_cast<int>(e));
    }
  std::vector<char> seen(static_cast<size_t>(body.mesh.num_nodes()), 0);
  for (int e : moved)
    for (int k = 0; k < body.mesh.nodes_per_elem(); ++k)
      if (const int n = body.mesh.element(e)[k]; !seen[n]) {
        seen[n] = 1;
        relink(n);
      }
  primed = true;
  return changed;
}

/// The facet-connected pieces of subdomain s (breadth first over the dual graph).
std::vector<std::vector<int>> PartitionReporter::State::pieces(int s, const std::vector<int>& elements) const {
  std::vector<char> seen(owner.size(), 0);
  std::vector<std::vector<int>> out;
  for (int start : elements) {
    if (seen[start]) continue;
    seen[start] = 1;
    std::vector<int> piece{start};
    for (size_t at = 0; at < piece.size(); ++at)
      for (const int* e = neighbours.begin(piece[at]); e != neighbours.end(piece[at]); ++e)
        if (owner[*e] == s && !seen[*e]) {
          seen[*e] = 1;
          piece.push_back(*e);
        }
    std::sort(piece.begin(), piece.end());
    out.push_back(std::move(piece));
  }
  return out;
}

SubdomainCache PartitionReporter::State::compute(int s, const std::vector<int>& elements) const {
  SubdomainCache c;
  SubdomainReport& r = c.report;
  r.id = s;
  r.elements = static_cast<int>(elements.size());
  if (elements.empty()) return c;  // its problem: empty_problems
  std::vector<int> local(static_cast<size_t>(body.mesh.num_nodes()), -1);
  const LocalPart sub = local_part(body, dofs, elements, local);
  r.nodes = sub.body.mesh.num_nodes();
  r.dofs = sub.dofs.num_free();
  r.rigid_modes = static_cast<int>(kernel_basis(sub.body.mesh, sub.dofs).cols());
  r.rigid_modes_after_split = r.rigid_modes;
  const std::vector<std::vector<int>> parts = pieces(s, elements);
  r.pieces = static_cast<int>(parts.size());
  if (parts.size() > 1) {
    r.rigid_modes_after_split = 0;
    for (const std::vector<int>& part : parts) {
      const LocalPart p = local_part(body, dofs, part, local);
      r.rigid_modes_after_split += static_cast<int>(kernel_basis(p.body.mesh, p.dofs).cols());
    }
    c.problems = subdomain_problems(sub.body.mesh, s, options.path);
  }
  r.factor = estimate_factor(sub.body.mesh, sub.dofs);
  return c;
}

void PartitionReporter::State::recompute(const std::vector<char>& changed) {
  std::vector<int> todo;
  for (size_t s = 0; s < changed.size(); ++s)
    if (changed[s]) todo.push_back(static_cast<int>(s));
  std::vector<std::vector<int>> elements(changed.size());
  for (size_t e = 0; e < owner.size(); ++e)
    if (owner[e] >= 0 && changed[owner[e]]) elements[owner[e]].push_back(static_cast<int>(e));
  cache.resize(changed.size());
  // the largest first: the threads finish together
  std::stable_sort(todo.begin(), todo.end(), [&](int a, int b) { return elements[a].size() > elements[b].size(); });
  for_each_group(todo.size(), options.threads, [&](size_t i) { cache[todo[i]] = compute(todo[i], elements[todo[i]]); });
  empty_problems(todo);
  recomputed = static_cast<int>(todo.size());
}

/// check_partition's "no elements" problem of every recomputed empty subdomain, from one call on an empty mesh
/// (which lists exactly one problem per subdomain, in order).
void PartitionReporter::State::empty_problems(const std::vector<int>& todo) {
  int top = -1;
  for (int s : todo)
    if (cache[s].report.elements == 0) top = std::max(top, s);
  if (top < 0) return;
  Mesh empty;
  empty.dim = body.mesh.dim;
  empty.type = body.mesh.type;
  std::vector<PartitionProblem> all = check_partition(empty, Partition{top + 1, {}, ""}, options.path);
  for (int s : todo)
    if (cache[s].report.elements == 0 && s < static_cast<int>(all.size())) cache[s].problems = {all[s]};
}

void PartitionReporter::State::assemble(std::vector<PartitionProblem> id_problems, bool with_subdomains) {
  PartitionReport r;
  r.body_elements = body.mesh.num_elements();
  r.body_dofs = dofs.num_free();
  r.one_domain = one_domain;
  r.one_domain_cost = one_domain_cost(one_domain);
  r.problems = std::move(id_problems);
  if (with_subdomains) {
    const bool ids_ok = r.problems.empty();
    r.multipliers = total_multipliers;
    r.paper_multipliers = total_paper;
    for (size_t s = 0; s < cache.size(); ++s) {
      SubdomainReport x = cache[s].report;
      x.multipliers = multipliers[s];
      x.paper_multipliers = paper[s];
      x.cost = predicted_cost(x.factor, options.cost);
      r.dofs += x.dofs;
      r.rigid_modes += x.rigid_modes;
      r.rigid_modes_after_split += x.rigid_modes_after_split;
      r.subdomain_factors.nnz += x.factor.nnz;
      r.subdomain_factors.flops += x.factor.flops;
      r.cost += x.cost;
      r.subdomains.push_back(x);
      if (ids_ok) r.problems.insert(r.problems.end(), cache[s].problems.begin(), cache[s].problems.end());
    }
    r.predicted_ratio = r.one_domain_cost > 0 ? r.cost / r.one_domain_cost : 0;
  }
  report = std::move(r);
}

PartitionReporter::PartitionReporter(const Body& body, const DofMap& dofs, ReporterOptions options)
    : state_(std::make_unique<State>(body, dofs, std::move(options))) {
  state_->assemble({}, false);
}

PartitionReporter::~PartitionReporter() = default;

const PartitionReport& PartitionReporter::update(const Partition& p) {
  State& st = *state_;
  const Mesh& m = st.body.mesh;
  st.recomputed = 0;
  if (p.element_subdomain.size() != static_cast<size_t>(m.num_elements()) || p.num_subdomains < 1) {
    st.assemble(check_partition(m, p, st.options.path), false);  // nothing to count; the state is kept
    return st.report;
  }
  std::vector<int> ids = p.element_subdomain;
  bool ids_ok = true;
  for (int& s : ids)
    if (s < 0 || s >= p.num_subdomains) {
      s = -1;
      ids_ok = false;
    }
  try {
    const std::vector<char> changed = st.move_elements(ids, p.num_subdomains);
    const std::vector<char> kept(changed.begin(), changed.begin() + p.num_subdomains);  // higher ids: now empty
    st.multipliers.resize(kept.size());
    st.paper.resize(kept.size());
    st.recompute(kept);
  } catch (...) {  // out of memory, or AMD failed: start afresh next time
    st.reset();
    throw;
  }
  // out-of-range ids: check_partition stops at them (cheaply, before looking at pieces)
  st.assemble(ids_ok ? std::vector<PartitionProblem>{} : check_partition(m, p, st.options.path), true);
  return st.report;
}

const PartitionReport& PartitionReporter::report() const { return state_->report; }

int PartitionReporter::last_recomputed() const { return state_->recomputed; }

}  // namespace rollsim
