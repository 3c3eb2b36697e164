// The output registry's names and output.fields' selection: every distinct name once, in the registry's order (stress
// and von_mises are a point and a cell array each); a name selects both of its arrays; `all`, or nothing, selects
// every field; any other name selects only itself.
#include <gtest/gtest.h>

#include <algorithm>

#include "io/OutputFields.h"

namespace test_output_fields {

using namespace rollsim;

TEST(OutputFields, NamesAreDistinctAndInTheRegistrysOrder) {
  const std::vector<std::string> names = output_field_names();
  const std::vector<std::string> expected{"displacement",     "stress",       "von_mises",
                                          "contact_pressure", "contact_slip", "contact_shear",
                                          "plastic_strain",   "temperature",  "jacobian_ratio"};
  EXPECT_EQ(names, expected);
  for (const OutputField& f : output_fields())
    EXPECT_NE(std::find(names.begin(), names.end(), f.name), names.end()) << f.name;
}

TEST(OutputFields, ANameSelectsItsPointAndCellArraysAndAllSelectsEveryField) {
  int stress = 0, selected_by_all = 0, selected_by_none = 0;
  for (const OutputField& f : output_fields()) {
    if (is_selected(f, {"stress", "plastic_strain"})) {
      EXPECT_TRUE(f.name == "stress" || f.name == "plastic_strain") << f.name;
      stress += f.name == "stress";
    }
    selected_by_all += is_selected(f, {kAllFields});
    selected_by_none += is_selected(f, {});
    EXPECT_FALSE(is_selected(f, {"no_such_field"})) << f.name;
  }
  EXPECT_EQ(stress, 2) << "the nodal average and the element mean";
  EXPECT_EQ(selected_by_all, static_cast<int>(output_fields().size()));
  EXPECT_EQ(selected_by_none, static_cast<int>(output_fields().size()));
}

}  // namespace test_output_fields
