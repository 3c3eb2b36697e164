#pragma once
// The run writer's FieldWriter (io/RunWriter.h) over this adapter's VTU and PVD writers.
#include <string>
#include <utility>

#include "io/RunWriter.h"

namespace rollsim {

class VtkFieldWriter final : public FieldWriter {
 public:
  /// `compression`: output.compression (lz4, zlib, none).
  explicit VtkFieldWriter(std::string compression = "lz4") : compression_(std::move(compression)) {}
  void write_result(const std::filesystem::path& file, const Model& model, const Results& results,
                    const std::vector<std::string>& fields) const override;
  void write_state(const std::filesystem::path& file, const Model& model, const Results& results, size_t increment,
                   const std::vector<std::string>& fields) const override;
  size_t write_increments(const std::filesystem::path& file, const Model& model, const Results& results,
                          const std::vector<std::string>& fields, const std::function<bool()>& stop) const override;

 private:
  std::string compression_;
};

}  // namespace rollsim
