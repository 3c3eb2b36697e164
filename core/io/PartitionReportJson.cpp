#include "io/PartitionReportJson.h"

#include <nlohmann/json.hpp>

namespace rollsim {

namespace {
using json = nlohmann::ordered_json;

json subdomain_json(const SubdomainReport& s) {
  return {{"id", s.id},
          {"elements", s.elements},
          {"dofs", s.dofs},
          {"multipliers", s.multipliers},
          {"rigid_modes", s.rigid_modes_after_split},
          {"pieces", s.pieces},
          {"factor_nnz", s.factor.nnz},
          {"factor_flops", s.factor.flops},
          {"cost_flops", s.cost}};
}

json report_json(const BodyPartitionReport& b) {
  const PartitionReport& r = b.report;
  json subdomains = json::array();
  for (const SubdomainReport& s : r.subdomains) subdomains.push_back(subdomain_json(s));
  json problems = json::array();
  for (const PartitionProblem& p : r.problems) problems.push_back(p.message);
  return {{"body", b.body},
          {"subdomain_count", r.subdomains.size()},
          {"subdomains", subdomains},
          {"problems", problems},
          {"multipliers", r.multipliers},
          {"paper_multipliers", r.paper_multipliers},
          {"rigid_modes", r.rigid_modes_after_split},
          {"cost_flops", r.cost},
          {"one_domain_cost_flops", r.one_domain_cost},
          {"predicted_ratio", r.predicted_ratio}};
}
}  // namespace

std::string partition_report_json(const std::vector<BodyPartitionReport>& reports) {
  json bodies = json::array();
  for (const BodyPartitionReport& b : reports) bodies.push_back(report_json(b));
  return json{{"cost_model",
               "per subdomain: factorizations · flops(L_i) + (CG iterations · substitutions + 2) · 4 nnz(L_i), "
               "against one domain: flops(L_0) + 4 nnz(L_0) (docs/PARTITIONS.md, the partition table)"},
              {"bodies", bodies}}
      .dump(2);
}

}  // namespace rollsim
