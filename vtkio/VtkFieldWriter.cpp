#include "VtkFieldWriter.h"

#include "PvdWriter.h"
#include "VtuWriter.h"

namespace rollsim {

void VtkFieldWriter::write_result(const std::filesystem::path& file, const Model& model, const Results& results,
                                  const std::vector<std::string>& fields) const {
  write_vtu(file, model, results, fields);
}

void VtkFieldWriter::write_increments(const std::filesystem::path& file, const Model& model, const Results& results,
                                      const std::vector<std::string>& fields) const {
  write_increment_collection(file, model, results, fields);
}

}  // namespace rollsim
