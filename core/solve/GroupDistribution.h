#pragma once
// How a strategy's groups are spread over processes: which groups this process holds (assembles, factors, solves
// with), and the one collective operation that joins what each computed — a sum every process receives bit for bit
// alike (so that every process takes the same decisions). One process holds every group and sums nothing; under
// `petsc` with `petsc_method: mixed` the module rollsim_petsc.so gives an MPI one (group g on rank g mod P). The
// engine knows this interface only, never MPI.
#include <Eigen/Dense>
#include <cstddef>

namespace rollsim {

class GroupDistribution {
 public:
  virtual ~GroupDistribution() = default;
  /// The process (MPI rank) that holds group g.
  virtual int holder(size_t group) const = 0;
  /// This process's number (MPI rank) and how many there are.
  virtual int process() const = 0;
  virtual int processes() const = 0;
  /// True when this process holds group g.
  bool holds(size_t group) const { return holder(group) == process(); }
  /// x summed over every process, in place; every process receives the same bits. A value only its holder computed
  /// (the others' are zero) comes back exact: this is also the gather.
  virtual void sum(Eigen::VectorXd& x) const = 0;
};

}  // namespace rollsim
