// Reverse Cuthill-McKee ordering with George-Liu pseudo-peripheral roots; skyline column heights and profile.
#include "solve/ReverseCuthillMcKee.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace rollsim {
namespace {

/// Symmetric adjacency (no self loops) of the first m vertices of the graph of A, in compressed form.
struct Graph {
  std::vector<int> start;  // neighbours of v: adj[start[v] .. start[v+1])
  std::vector<int> adj;
  int size() const { return static_cast<int>(start.size()) - 1; }
  int degree(int v) const { return start[v + 1] - start[v]; }
};

Graph build_graph(const SparseMatrix& A, int m) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(static_cast<size_t>(A.nonZeros()));
  for (int c = 0; c < m; ++c)
    for (SparseMatrix::InnerIterator it(A, c); it; ++it) {
      const int r = static_cast<int>(it.row());
      if (r < m && r != c) {
        edges.emplace_back(c, r);
        edges.emplace_back(r, c);  // tolerate a pattern that is not exactly symmetric
      }
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  Graph g;
  g.start.assign(static_cast<size_t>(m) + 1, 0);
  g.adj.reserve(edges.size());
  for (const auto& [v, w] : edges) {
    ++g.start[v + 1];
    g.adj.push_back(w);
  }
  std::partial_sum(g.start.begin(), g.start.end(), g.start.begin());
  return g;
}

/// Rooted level structure: levels l hold nodes[first[l] .. first[l+1]).
struct Levels {
  std::vector<int> nodes;
  std::vector<int> first;
  int count() const { return static_cast<int>(first.size()) - 1; }
};

/// Breadth-first levels from `root` within its component; `stamp`/`mark` avoid clearing a visited array each time.
Levels root_levels(const Graph& g, int root, std::vector<int>& stamp, int mark) {
  Levels ls{{root}, {0}};
  stamp[root] = mark;
  for (size_t begin = 0; begin < ls.nodes.size();) {
    const size_t end = ls.nodes.size();
    for (size_t k = begin; k < end; ++k)
      for (int e = g.start[ls.nodes[k]]; e < g.start[ls.nodes[k] + 1]; ++e)
        if (stamp[g.adj[e]] != mark) {
          stamp[g.adj[e]] = mark;
          ls.nodes.push_back(g.adj[e]);
        }
    ls.first.push_back(static_cast<int>(end));
    begin = end;
  }
  return ls;
}

/// George-Liu (SPARSPAK FNROOT): move to a minimum-degree node of the last level while the eccentricity grows.
int pseudo_peripheral_node(const Graph& g, int start, std::vector<int>& stamp, int& mark) {
  int root = start;
  Levels ls = root_levels(g, root, stamp, ++mark);
  const int component = static_cast<int>(ls.nodes.size());
  while (ls.count() > 1 && ls.count() < component) {
    const int last = ls.first[ls.count() - 1];
    int candidate = ls.nodes[last];
    for (int k = last + 1; k < component; ++k)
      if (g.degree(ls.nodes[k]) < g.degree(candidate)) candidate = ls.nodes[k];
    Levels next = root_levels(g, candidate, stamp, ++mark);
    const bool deeper = next.count() > ls.count();
    root = candidate;
    ls = std::move(next);
    if (!deeper) break;
  }
  return root;
}

/// Cuthill-McKee numbering of the component of `root`, appended to `order`.
void cuthill_mckee(const Graph& g, int root, std::vector<char>& numbered, std::vector<int>& order) {
  size_t head = order.size();
  order.push_back(root);
  numbered[root] = 1;
  std::vector<int> fresh;
  const auto by_degree = [&g](int v, int w) {
    return g.degree(v) < g.degree(w) || (g.degree(v) == g.degree(w) && v < w);
  };
  for (; head < order.size(); ++head) {
    const int v = order[head];
    fresh.clear();
    for (int e = g.start[v]; e < g.start[v + 1]; ++e)
      if (!numbered[g.adj[e]]) {
        numbered[g.adj[e]] = 1;
        fresh.push_back(g.adj[e]);
      }
    std::sort(fresh.begin(), fresh.end(), by_degree);
    order.insert(order.end(), fresh.begin(), fresh.end());
  }
}

}  // namespace

std::vector<int> reverse_cuthill_mckee(const SparseMatrix& A, int trailing) {
  if (A.rows() != A.cols()) throw std::invalid_argument("reverse_cuthill_mckee: matrix is not square");
  const int n = static_cast<int>(A.cols());
  if (trailing < 0 || trailing > n) throw std::invalid_argument("reverse_cuthill_mckee: bad trailing count");
  const int m = n - trailing;
  const Graph g = build_graph(A, m);
  std::vector<int> order;
  order.reserve(static_cast<size_t>(n));
  std::vector<char> numbered(static_cast<size_t>(m), 0);
  std::vector<int> stamp(static_cast<size_t>(m), 0);
  int mark = 0;
  for (int s = 0; s < m; ++s)
    if (!numbered[s]) cuthill_mckee(g, pseudo_peripheral_node(g, s, stamp, mark), numbered, order);
  std::reverse(order.begin(), order.end());
  for (int k = m; k < n; ++k) order.push_back(k);
  return order;
}

std::vector<int> skyline_first_rows(const SparseMatrix& A, const std::vector<int>& perm) {
  const int n = static_cast<int>(A.cols());
  if (A.rows() != A.cols() || static_cast<int>(perm.size()) != n)
    throw std::invalid_argument("skyline_first_rows: sizes do not match");
  std::vector<int> inverse(static_cast<size_t>(n), -1);
  for (int k = 0; k < n; ++k) {
    if (perm[k] < 0 || perm[k] >= n || inverse[perm[k]] >= 0)
      throw std::invalid_argument("skyline_first_rows: not a permutation");
    inverse[perm[k]] = k;
  }
  std::vector<int> first(static_cast<size_t>(n));
  std::iota(first.begin(), first.end(), 0);
  for (int c = 0; c < n; ++c)
    for (SparseMatrix::InnerIterator it(A, c); it; ++it) {
      const int i = inverse[it.row()], j = inverse[c];
      if (i < j)
        first[j] = std::min(first[j], i);
      else
        first[i] = std::min(first[i], j);  // mirror: tolerate a pattern that is not exactly symmetric
    }
  return first;
}

long profile_size(const SparseMatrix& A, const std::vector<int>& perm) {
  const std::vector<int> first = skyline_first_rows(A, perm);
  long total = 0;
  for (int j = 0; j < static_cast<int>(first.size()); ++j) total += j - first[j] + 1;
  return total;
}

}  // namespace rollsim
