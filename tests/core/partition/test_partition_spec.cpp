// The CLI / project spelling of partitions ("4x4", "2x2x1", "metis:16") and its error messages.
#include <gtest/gtest.h>

#include "PartitionFixtures.h"
#include "partition/PartitionSpec.h"

namespace test_partition_spec {

using namespace rollsim;

namespace {
std::string error_of(const std::string& text) {
  try {
    parse_partition_spec(text);
  } catch (const PartitionError& e) {
    EXPECT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems().front().path, "partition");
    return e.problems().front().message;
  }
  return "no error";
}
}  // namespace

TEST(PartitionSpec, ParsesSlicesAndMetis) {
  PartitionSpec s = parse_partition_spec("4x4");
  EXPECT_EQ(s.kind, PartitionKind::Structured);
  EXPECT_EQ(s.slices, (std::array<int, 3>{4, 4, 1}));
  EXPECT_EQ(s.axes, 2);
  s = parse_partition_spec(" 2X2x1 ");
  EXPECT_EQ(s.slices, (std::array<int, 3>{2, 2, 1}));
  EXPECT_EQ(s.axes, 3);
  EXPECT_EQ(to_string(s), "2x2x1");
  s = parse_partition_spec("metis:16");
  EXPECT_EQ(s.kind, PartitionKind::Metis);
  EXPECT_EQ(s.parts, 16);
  EXPECT_EQ(to_string(s), "metis:16");
  EXPECT_EQ(parse_partition_spec("METIS:3").parts, 3);
}

TEST(PartitionSpec, ClearErrors) {
  EXPECT_NE(error_of("").find("empty partition"), std::string::npos);
  EXPECT_NE(error_of("4x").find("expected slice counts such as \"4x4\""), std::string::npos);
  EXPECT_NE(error_of("4x4x4x4").find("expected slice counts"), std::string::npos);
  EXPECT_NE(error_of("-1x4").find("expected slice counts"), std::string::npos);
  EXPECT_NE(error_of("banana").find("\"banana\""), std::string::npos);
  EXPECT_NE(error_of("0x4").find("the slice count along x must be at least 1"), std::string::npos);
  EXPECT_NE(error_of("4x0").find("along y"), std::string::npos);
  EXPECT_NE(error_of("metis:").find("must be a positive integer"), std::string::npos);
  EXPECT_NE(error_of("metis:abc").find("must be a positive integer"), std::string::npos);
  EXPECT_NE(error_of("metis:0").find("at least 1"), std::string::npos);
  EXPECT_NE(error_of("99999999999x2").find("expected slice counts"), std::string::npos);
}

TEST(PartitionSpec, MakePartitionChecksTheBody) {
  const Model m2 = test::block_model(2, {4, 4, 1});
  EXPECT_EQ(make_partition(m2.bodies[0].mesh, parse_partition_spec("2x2x1")).num_subdomains, 4);
  try {
    make_partition(m2.bodies[0].mesh, parse_partition_spec("2x2x2"));
    FAIL() << "a z slicing of a 2D body must be refused";
  } catch (const PartitionError& e) {
    EXPECT_NE(std::string(e.what()).find("a 2D body cannot be sliced along z"), std::string::npos);
  }
  EXPECT_THROW(make_partition(m2.bodies[0].mesh, parse_partition_spec("metis:17")), PartitionError);
  PartitionSpec painted;
  painted.kind = PartitionKind::Explicit;
  painted.map = std::vector<int>(16, 0);
  painted.map[5] = 2;
  const Partition p = make_partition(m2.bodies[0].mesh, painted);
  EXPECT_EQ(p.num_subdomains, 3);  // largest id + 1
  EXPECT_EQ(p.description, "explicit");
}

}  // namespace test_partition_spec
