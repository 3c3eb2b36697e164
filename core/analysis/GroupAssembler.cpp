#include "analysis/GroupAssembler.h"

#include <numeric>
#include <stdexcept>

#include "fem/Assembler.h"

namespace rollsim {

void GroupAssembler::assemble(const std::vector<size_t>& groups, const std::vector<Eigen::VectorXd>& u_free,
                              double load_factor, BlockSystem& sys) const {
  if (sys.groups.size() != sources_.size())
    throw std::logic_error("GroupAssembler: the system has " + std::to_string(sys.groups.size()) +
                           " groups, the assembler knows " + std::to_string(sources_.size()));
  for (size_t g : groups) {
    const GroupSource& src = sources_[g];
    const bool at_rest = g >= u_free.size() || u_free[g].size() == 0;
    const Eigen::VectorXd u =
        src.dofs->expand(at_rest ? Eigen::VectorXd::Zero(src.dofs->num_free()) : u_free[g], load_factor);
    Group& group = sys.groups[g];
    Eigen::VectorXd f_int;
    Assembler(*src.body, *src.dofs).assemble(u, group.K, f_int);
    group.f = src.dofs->restrict_to_free(load_factor * src.nodal_load) - f_int;
  }
}

std::vector<size_t> all_groups(const BlockSystem& sys) {
  std::vector<size_t> all(sys.groups.size());
  std::iota(all.begin(), all.end(), size_t{0});
  return all;
}

}  // namespace rollsim
