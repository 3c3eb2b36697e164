#include "partition/DualGraph.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace rollsim {

namespace {
constexpr int kPad = std::numeric_limits<int>::max();

struct FacetKey {
  std::array<int, 4> sorted;  // sorted node ids, padded with kPad in 2D
  int element;
  int local;
};

std::vector<FacetKey> all_facets(const Mesh& m) {
  const int nf = m.dim == 2 ? 4 : 6;
  std::vector<std::vector<int>> table;
  for (int f = 0; f < nf; ++f) table.push_back(facet_local_nodes(m.type, f));
  std::vector<FacetKey> keys;
  keys.reserve(static_cast<size_t>(m.num_elements()) * nf);
  for (int e = 0; e < m.num_elements(); ++e)
    for (int f = 0; f < nf; ++f) {
      FacetKey k{{kPad, kPad, kPad, kPad}, e, f};
      for (size_t i = 0; i < table[f].size(); ++i) k.sorted[i] = m.element(e)[table[f][i]];
      std::sort(k.sorted.begin(), k.sorted.end());
      keys.push_back(k);
    }
  std::sort(keys.begin(), keys.end(), [](const FacetKey& x, const FacetKey& y) {
    return x.sorted != y.sorted ? x.sorted < y.sorted : x.element < y.element;
  });
  return keys;
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}
}  // namespace

std::vector<SharedFacet> shared_facets(const Mesh& m) {
  const std::vector<FacetKey> keys = all_facets(m);
  const int nfn = m.dim == 2 ? 2 : 4;
  std::vector<SharedFacet> shared;
  for (size_t i = 0; i < keys.size();) {
    size_t j = i + 1;
    while (j < keys.size() && keys[j].sorted == keys[i].sorted) ++j;
    for (size_t p = i; p < j; ++p)  // a conforming mesh has runs of 1 or 2; more would be a non-manifold facet
      for (size_t q = p + 1; q < j; ++q)
        if (keys[p].element != keys[q].element)
          shared.push_back({keys[p].element, keys[q].element, keys[i].sorted, nfn});
    i = j;
  }
  std::sort(shared.begin(), shared.end(),
            [](const SharedFacet& x, const SharedFacet& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  return shared;
}

DualGraph dual_graph(int num_elements, const std::vector<SharedFacet>& facets) {
  std::vector<std::vector<int>> adj(static_cast<size_t>(num_elements));
  for (const SharedFacet& f : facets) {
    adj[f.a].push_back(f.b);
    adj[f.b].push_back(f.a);
  }
  DualGraph g;
  g.xadj.push_back(0);
  for (auto& list : adj) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    g.adjncy.insert(g.adjncy.end(), list.begin(), list.end());
    g.xadj.push_back(static_cast<int>(g.adjncy.size()));
  }
  return g;
}

std::vector<int> connected_components(int num_elements, const std::vector<SharedFacet>& facets,
                                      const std::vector<int>* group) {
  std::vector<int> parent(static_cast<size_t>(num_elements));
  std::iota(parent.begin(), parent.end(), 0);
  for (const SharedFacet& f : facets)
    if (!group || (*group)[f.a] == (*group)[f.b]) {
      const int ra = find_root(parent, f.a), rb = find_root(parent, f.b);
      if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
    }
  std::vector<int> label(static_cast<size_t>(num_elements), -1), root_label(static_cast<size_t>(num_elements), -1);
  int next = 0;
  for (int e = 0; e < num_elements; ++e) {
    const int r = find_root(parent, e);
    if (root_label[r] < 0) root_label[r] = next++;
    label[e] = root_label[r];
  }
  return label;
}

}  // namespace rollsim
