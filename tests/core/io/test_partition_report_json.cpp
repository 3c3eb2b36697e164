// partition.json (`rollsim mesh --partition`): the window's partition table, written for batch users.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../partition/PartitionFixtures.h"
#include "io/PartitionReportJson.h"
#include "partition/PartitionReport.h"
#include "partition/StructuredPartition.h"

namespace rollsim::test_partition_report_json {
namespace {

TEST(PartitionReportJson, CarriesTheTableAndThePrediction) {
  Model m = test::block_model(2, {12, 8, 1});
  test::support(m, test::nodes_in_box(m, {-1, -1, -1}, {1e-9, 1e9, 1}));  // the left edge clamped
  const DofMap dofs(m.bodies[0], 0, m.displacements);
  PartitionReporter reporter(m.bodies[0], dofs);
  const PartitionReport& r = reporter.update(structured_partition(m.bodies[0].mesh, {3, 2, 1}));
  const auto j = nlohmann::json::parse(partition_report_json({{"block", r}}));
  ASSERT_EQ(j.at("bodies").size(), 1u);
  const auto& b = j.at("bodies")[0];
  EXPECT_EQ(b.at("body"), "block");
  ASSERT_EQ(b.at("subdomains").size(), 6u);
  int elements = 0;
  for (const auto& s : b.at("subdomains")) elements += s.at("elements").get<int>();
  EXPECT_EQ(elements, 12 * 8);
  EXPECT_EQ(b.at("multipliers").get<long>(), r.multipliers);
  EXPECT_EQ(b.at("rigid_modes").get<long>(), r.rigid_modes_after_split);
  EXPECT_GT(r.rigid_modes_after_split, 0);  // the subdomains away from the clamp float
  EXPECT_DOUBLE_EQ(b.at("predicted_ratio").get<double>(), r.cost / r.one_domain_cost);
  EXPECT_TRUE(b.at("problems").empty());
}

}  // namespace
}  // namespace rollsim::test_partition_report_json
