#include "VtkFieldWriter.h"

#include "PvdWriter.h"
#include "VtuWriter.h"

namespace rollsim {

void VtkFieldWriter::write_result(const std::filesystem::path& file, const Model& model, const Results& results,
                                  const std::vector<std::string>& fields) const {
  const double load_factor = results.increments.empty() ? 1.0 : results.increments.back().load_factor;
  write_vtu(file, results.model ? *results.model : model, results, fields,
            {compression_, state_values(results, load_factor)});
}

void VtkFieldWriter::write_state(const std::filesystem::path& file, const Model& model, const Results& results,
                                 size_t increment, const std::vector<std::string>& fields) const {
  const IncrementResults& state = results.increments.at(increment);
  write_vtu(file, model_of(state, model), state.bodies, fields,
            {compression_, state_values(results, state.load_factor)});
}

size_t VtkFieldWriter::write_increments(const std::filesystem::path& file, const Model& model, const Results& results,
                                        const std::vector<std::string>& fields,
                                        const std::function<bool()>& stop) const {
  return write_increment_collection(file, model, results, fields, stop, compression_).size();
}

}  // namespace rollsim
