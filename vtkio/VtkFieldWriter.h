#pragma once
// The run writer's FieldWriter (io/RunWriter.h) over this adapter's VTU and PVD writers.
#include "io/RunWriter.h"

namespace rollsim {

class VtkFieldWriter final : public FieldWriter {
 public:
  void write_result(const std::filesystem::path& file, const Model& model, const Results& results,
                    const std::vector<std::string>& fields) const override;
  void write_increments(const std::filesystem::path& file, const Model& model, const Results& results,
                        const std::vector<std::string>& fields) const override;
};

}  // namespace rollsim
