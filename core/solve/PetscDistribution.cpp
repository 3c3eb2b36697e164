// The groups over MPI ranks for the core's mixed method (`petsc_method: mixed`; solve/GroupDistribution.h): group g
// on rank g mod P, sums reduced on rank 0 and broadcast, so every rank receives the same bits (an all-reduce may add
// in a different order on each rank, and the ranks' Krylov solves and Newton decisions must not part). Part of the
// module rollsim_petsc.so: the core reaches it through PetscModule's table.
#include "solve/PetscDistribution.h"

#include "solve/PetscSupport.h"

namespace rollsim {

namespace {

class MpiGroups final : public GroupDistribution {
 public:
  MpiGroups() : rank_(petsc::rank()), ranks_(petsc::ranks()) {}
  int holder(size_t group) const override { return static_cast<int>(group % static_cast<size_t>(ranks_)); }
  int process() const override { return rank_; }
  int processes() const override { return ranks_; }
  void sum(Eigen::VectorXd& x) const override {
    if (ranks_ == 1 || x.size() == 0) return;
    Eigen::VectorXd total(x.size());
    MPI_Reduce(x.data(), total.data(), static_cast<int>(x.size()), MPI_DOUBLE, MPI_SUM, 0, PETSC_COMM_WORLD);
    if (rank_ == 0) x = total;
    MPI_Bcast(x.data(), static_cast<int>(x.size()), MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  }

 private:
  int rank_, ranks_;
};

}  // namespace

std::shared_ptr<const GroupDistribution> mpi_group_distribution() {
  petsc::start();
  return std::make_shared<MpiGroups>();
}

}  // namespace rollsim
