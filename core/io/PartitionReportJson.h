#pragma once
// partition.json: the window's partition table for batch users (`rollsim mesh --partition`) — per subdomain the
// counts FETI will see and the estimated Cholesky cost, and the partition's predicted cost against one domain.
#include <string>
#include <vector>

#include "partition/PartitionReport.h"

namespace rollsim {

struct BodyPartitionReport {
  std::string body;
  PartitionReport report;
};

/// The JSON text (2-space indented) of the reports, one per partitioned body.
std::string partition_report_json(const std::vector<BodyPartitionReport>& reports);

}  // namespace rollsim
