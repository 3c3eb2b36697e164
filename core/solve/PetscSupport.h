#pragma once
// What the `petsc` module's strategies share (rollsim_petsc.so only, never the core): PETSc and MPI started and ended
// once, PETSc's error codes as exceptions, and refusals taken by every rank together so that none is left waiting in
// a collective call.
#include <petscvec.h>

#include <Eigen/Dense>

#include <string>

namespace rollsim::petsc {

/// Starts PETSc and MPI once (start_processes of PetscStrategy.h).
void start();
/// This process's MPI rank, 0 before PETSc starts (process_rank).
int rank();
/// The number of MPI ranks (1 before PETSc starts).
int ranks();
/// Ends PETSc and MPI when start() started them (finish_processes).
void finish();

/// Throws std::invalid_argument naming `call` when PETSc returned an error.
void check(PetscErrorCode code, const char* call);
#define ROLLSIM_PETSC(call) ::rollsim::petsc::check((call), #call)

/// True on every rank when `ok` holds on every rank: no rank leaves for an error the others did not see.
bool on_all_ranks(bool ok);
/// Throws on every rank when any rank has a message (an MPI_Allreduce of the error flag first).
void refuse_together(const std::string& message);
/// The whole of a distributed vector on every rank (VecScatterCreateToAll).
Eigen::VectorXd on_every_rank(Vec x);
/// --petsc-options (solver.petsc_options) handed to PETSc before a strategy's first solve and checked after it: an
/// option PETSc did not use (misspelt, or meant for another method) is refused.
class PassedOptions {
 public:
  PassedOptions(std::string options, std::string method) : options_(std::move(options)), method_(std::move(method)) {}
  /// Before a solve: the options into PETSc's database, the first time.
  void insert() const;
  /// After a whole solve (every option a viewer or monitor reads has been read then), the first time: the message
  /// refusing what PETSc did not use, "" when it used everything (and every later time). The same on every rank.
  std::string unused();

 private:
  std::string options_, method_;
  bool checked_ = false;
};

}  // namespace rollsim::petsc
