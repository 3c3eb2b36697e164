#include "partition/MetisPartition.h"

#include <metis.h>

#include <algorithm>

#include "partition/DualGraph.h"

namespace rollsim {

namespace {
void check_parts(const Mesh& mesh, int parts) {
  const std::string spelled = "metis:" + std::to_string(parts);
  if (parts < 1) throw PartitionError({{"partition", spelled + ": the number of subdomains must be at least 1"}});
  if (parts > mesh.num_elements())
    throw PartitionError({{"partition", spelled + ": more subdomains than the body's " +
                                            std::to_string(mesh.num_elements()) + " elements"}});
}

bool is_connected(int num_elements, const std::vector<SharedFacet>& facets) {
  const std::vector<int> c = connected_components(num_elements, facets);
  return c.empty() || *std::max_element(c.begin(), c.end()) == 0;
}
}  // namespace

Partition metis_partition(const Mesh& mesh, int parts) {
  check_parts(mesh, parts);
  Partition p;
  p.num_subdomains = parts;
  p.description = "metis:" + std::to_string(parts);
  p.element_subdomain.assign(static_cast<size_t>(mesh.num_elements()), 0);
  if (parts == 1) return p;
  const std::vector<SharedFacet> facets = shared_facets(mesh);
  const DualGraph g = dual_graph(mesh.num_elements(), facets);
  std::vector<idx_t> xadj(g.xadj.begin(), g.xadj.end()), adjncy(g.adjncy.begin(), g.adjncy.end());
  std::vector<idx_t> part(static_cast<size_t>(mesh.num_elements()), 0);
  idx_t nvtxs = mesh.num_elements(), ncon = 1, nparts = parts, objval = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_CONTIG] = is_connected(mesh.num_elements(), facets) ? 1 : 0;
  const int status = METIS_PartGraphKway(&nvtxs, &ncon, xadj.data(), adjncy.data(), nullptr, nullptr, nullptr, &nparts,
                                         nullptr, nullptr, options, &objval, part.data());
  if (status != METIS_OK)
    throw PartitionError(
        {{"partition", p.description + ": METIS_PartGraphKway failed (status " + std::to_string(status) + ")"}});
  for (size_t e = 0; e < part.size(); ++e) p.element_subdomain[e] = static_cast<int>(part[e]);
  return p;
}

}  // namespace rollsim
