#include "solve/PetscSupport.h"

#include <stdexcept>

namespace rollsim::petsc {

namespace {
bool started_here = false;

/// MPI_Comm_rank or MPI_Comm_size of PETSc's world, `before` until PETSc starts.
int of_world(int (*ask)(MPI_Comm, int*), int before) {
  PetscBool up = PETSC_FALSE;
  PetscInitialized(&up);
  if (!up) return before;
  int value = before;
  ask(PETSC_COMM_WORLD, &value);
  return value;
}
}  // namespace

void start() {
  PetscBool up = PETSC_FALSE;
  PetscInitialized(&up);
  if (up) return;
  if (static_cast<int>(PetscInitializeNoArguments()) != 0)
    throw std::invalid_argument("petsc: PetscInitializeNoArguments failed (MPI or PETSc could not start)");
  started_here = true;
}

int rank() { return of_world(MPI_Comm_rank, 0); }

int ranks() { return of_world(MPI_Comm_size, 1); }

void finish() {
  if (started_here) PetscFinalize();
  started_here = false;
}

void check(PetscErrorCode code, const char* call) {
  if (static_cast<int>(code) != 0)
    throw std::invalid_argument(std::string("petsc: ") + call + " failed (PETSc error " +
                                std::to_string(static_cast<int>(code)) + ")");
}

bool on_all_ranks(bool ok) {
  int local = ok ? 1 : 0, global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
  return global == 1;
}

void refuse_together(const std::string& message) {
  if (on_all_ranks(message.empty())) return;
  throw std::invalid_argument(message.empty() ? "petsc: another MPI rank refused the problem (see its message)"
                                              : message);
}

void PassedOptions::insert() const {
  if (!checked_ && !options_.empty()) ROLLSIM_PETSC(PetscOptionsInsertString(nullptr, options_.c_str()));
}

std::string PassedOptions::unused() {
  if (checked_) return "";
  checked_ = true;
  PetscInt n = 0;
  char **names = nullptr, **values = nullptr;
  ROLLSIM_PETSC(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  std::string left;
  for (PetscInt i = 0; i < n; ++i) {
    const std::string name = names[i][0] == '-' ? names[i] + 1 : names[i];
    if (name == "log_view" || name == "options_left") continue;  // read at PetscFinalize
    left += (left.empty() ? "-" : ", -") + name;
  }
  ROLLSIM_PETSC(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  if (left.empty()) return "";
  return "petsc: --petsc-options: PETSc did not use " + left + " (misspelt, or not an option of --petsc-method " +
         method_ + ")";
}

Eigen::VectorXd on_every_rank(Vec x) {
  VecScatter all = nullptr;
  Vec xall = nullptr;
  ROLLSIM_PETSC(VecScatterCreateToAll(x, &all, &xall));
  ROLLSIM_PETSC(VecScatterBegin(all, x, xall, INSERT_VALUES, SCATTER_FORWARD));
  ROLLSIM_PETSC(VecScatterEnd(all, x, xall, INSERT_VALUES, SCATTER_FORWARD));
  PetscInt size = 0;
  ROLLSIM_PETSC(VecGetSize(xall, &size));
  const PetscScalar* values = nullptr;
  ROLLSIM_PETSC(VecGetArrayRead(xall, &values));
  Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(values, size);
  ROLLSIM_PETSC(VecRestoreArrayRead(xall, &values));
  VecScatterDestroy(&all);
  VecDestroy(&xall);
  return out;
}
}  // namespace rollsim::petsc
