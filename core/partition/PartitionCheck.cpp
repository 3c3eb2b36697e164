#include "partition/PartitionCheck.h"

#include <algorithm>
#include <map>

#include "partition/DualGraph.h"

namespace rollsim {

namespace {
std::string sizes_text(const std::vector<std::vector<int>>& pieces) {
  std::string s;
  for (size_t i = 0; i < pieces.size(); ++i)
    s += (i == 0 ? "" : i + 1 == pieces.size() ? " and " : ", ") + std::to_string(pieces[i].size());
  return s;
}

/// Out-of-range ids, reported once with the first offending element and how many more there are.
void check_ids(const Partition& p, const std::string& path, std::vector<PartitionProblem>& out) {
  std::vector<int> bad;
  for (size_t e = 0; e < p.element_subdomain.size(); ++e)
    if (p.element_subdomain[e] < 0 || p.element_subdomain[e] >= p.num_subdomains) bad.push_back(static_cast<int>(e));
  if (bad.empty()) return;
  const int e = bad.front();
  std::string more = bad.size() > 1 ? " (and " + std::to_string(bad.size() - 1) + " more elements out of range)" : "";
  out.push_back({path + ".map[" + std::to_string(e) + "]",
                 "element " + std::to_string(e) + ": subdomain id " + std::to_string(p.element_subdomain[e]) +
                     " is out of range 0.." + std::to_string(p.num_subdomains - 1) + more});
}
}  // namespace

std::vector<std::vector<std::vector<int>>> subdomain_pieces(const Mesh& mesh, const Partition& p) {
  const std::vector<int> comp = connected_components(mesh.num_elements(), shared_facets(mesh), &p.element_subdomain);
  std::vector<std::map<int, std::vector<int>>> by_comp(static_cast<size_t>(p.num_subdomains));
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const int s = p.element_subdomain[e];
    if (s >= 0 && s < p.num_subdomains) by_comp[s][comp[e]].push_back(e);  // bad ids: check_partition's job
  }
  std::vector<std::vector<std::vector<int>>> pieces(by_comp.size());
  for (size_t s = 0; s < by_comp.size(); ++s) {
    for (auto& [c, elems] : by_comp[s]) pieces[s].push_back(std::move(elems));
    std::stable_sort(pieces[s].begin(), pieces[s].end(),
                     [](const std::vector<int>& x, const std::vector<int>& y) { return x.size() > y.size(); });
  }
  return pieces;
}

std::vector<PartitionProblem> check_partition(const Mesh& mesh, const Partition& p, const std::string& path) {
  std::vector<PartitionProblem> out;
  const size_t ne = static_cast<size_t>(mesh.num_elements());
  if (p.element_subdomain.size() != ne) {
    out.push_back({path + ".map", "has " + std::to_string(p.element_subdomain.size()) + " entries, but the body has " +
                                      std::to_string(ne) + " elements (one subdomain id per element)"});
    return out;
  }
  if (p.num_subdomains < 1) {
    out.push_back({path, "needs at least one subdomain"});
    return out;
  }
  check_ids(p, path, out);
  if (!out.empty()) return out;
  const auto pieces = subdomain_pieces(mesh, p);
  const std::string joint = mesh.dim == 2 ? "edge" : "face";
  for (size_t s = 0; s < pieces.size(); ++s) {
    const std::string where = path + ".subdomains[" + std::to_string(s) + "]";
    if (pieces[s].empty()) out.push_back({where, "subdomain " + std::to_string(s) + " has no elements"});
    if (pieces[s].size() > 1)
      out.push_back({where, "subdomain " + std::to_string(s) + " is made of " + std::to_string(pieces[s].size()) +
                                " disconnected pieces (" + sizes_text(pieces[s]) + " elements) that share no " + joint +
                                "; split it (automatic splitting is available) or repaint it"});
  }
  return out;
}

namespace {
/// The subdomain id of a "<path>.subdomains[<id>]" path, or −1.
long subdomain_of(const std::string& path) {
  const auto open = path.rfind(".subdomains[");
  return open == std::string::npos ? -1 : std::stol(path.substr(open + 12));
}

/// A problem's class: its message without the numbers in it.
std::string class_of(const std::string& message) {
  std::string key;
  for (char c : message)
    if (c < '0' || c > '9') key += c;
  return key;
}
}  // namespace

std::vector<PartitionProblem> one_per_class(const std::vector<PartitionProblem>& problems) {
  std::vector<PartitionProblem> out;
  std::map<std::string, std::pair<size_t, std::vector<long>>> classes;  // class -> (index in out, subdomain ids)
  for (const PartitionProblem& p : problems) {
    const long s = subdomain_of(p.path);
    if (s < 0) {
      out.push_back(p);
      continue;
    }
    auto [it, first] = classes.try_emplace(class_of(p.message), out.size(), std::vector<long>{});
    it->second.second.push_back(s);
    if (first) out.push_back(p);
  }
  for (const auto& [key, where] : classes) {
    const std::vector<long>& ids = where.second;
    if (ids.size() < 2) continue;
    std::string list;
    for (size_t i = 1; i < ids.size() && i < 6; ++i) list += (i == 1 ? "" : ", ") + std::to_string(ids[i]);
    out[where.first].message +=
        " (so do subdomains " + list + (ids.size() > 6 ? ", …" : "") + ": " + std::to_string(ids.size()) + " in all)";
  }
  return out;
}

std::vector<std::string> split_disconnected(const Mesh& mesh, Partition& p) {
  std::vector<std::string> warnings;
  const auto pieces = subdomain_pieces(mesh, p);
  for (size_t s = 0; s < pieces.size(); ++s) {
    if (pieces[s].size() < 2) continue;
    std::string ids = std::to_string(s);
    for (size_t k = 1; k < pieces[s].size(); ++k) {
      for (int e : pieces[s][k]) p.element_subdomain[e] = p.num_subdomains;
      ids += (k + 1 == pieces[s].size() ? " and " : ", ") + std::to_string(p.num_subdomains++);
    }
    warnings.push_back("subdomain " + std::to_string(s) + " was made of " + std::to_string(pieces[s].size()) +
                       " disconnected pieces (" + sizes_text(pieces[s]) + " elements); split automatically into " +
                       "subdomains " + ids);
  }
  return warnings;
}

}  // namespace rollsim
