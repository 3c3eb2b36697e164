#pragma once
// How a strategy's groups are spread over processes: which groups this process holds (assembles, factors, solves
// with), and the one collective operation that joins what each computed — a sum every process receives bit for bit
// alike (so that every process takes the same decisions). One process holds every group and sums nothing; under
// `petsc` with `petsc_method: mixed` the module rollsim_petsc.so gives an MPI one (group g on rank g mod P). The
// engine knows this interface only, never MPI.
#include <Eigen/Dense>
#include <cstddef>
#include <vector>

#include "solve/BlockSystem.h"
#include "solve/Factorization.h"

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

/// Every group's kernel R_g as its holder has it (a finite-strain group's R is the kernel of the tangent its holder
/// assembled; another process's copy is the body's geometric modes), on every process.
std::vector<Eigen::MatrixXd> shared_kernels(const GroupDistribution& spread, const BlockSystem& sys);

/// Every group's vector (its holder's; the others hold zeros of its size) on every process.
void share_vectors(const GroupDistribution& spread, std::vector<Eigen::VectorXd>& per_group);

/// Throws the lowest group's SingularMatrix among `failed` (an empty message: that group factored, or another
/// process holds it); spread (not null), every process throws it alike, with the message of the group's holder.
void throw_first_failure(const GroupDistribution* spread, const std::vector<SingularMatrix>& failed);

/// More processes than groups: std::invalid_argument naming both counts and the ways out (every process alike).
void refuse_idle_processes(const GroupDistribution& spread, size_t groups);

}  // namespace rollsim
