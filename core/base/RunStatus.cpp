#include "base/RunStatus.h"

namespace rollsim {

const char* to_string(Status s) {
  switch (s) {
    case Status::converged:
      return "converged";
    case Status::not_converged:
      return "not_converged";
    case Status::diverged:
      return "diverged";
    case Status::cancelled:
      return "cancelled";
    case Status::error:
      return "error";
    case Status::no_bite:
      return "no_bite";
  }
  return "error";
}

const char* to_string(Reason r) {
  switch (r) {
    case Reason::none:
      return "";
    case Reason::iteration_limit:
      return "iteration_limit";
    case Reason::breakdown:
      return "breakdown";
    case Reason::round_off:
      return "round_off";
    case Reason::active_set_cycling:
      return "active_set_cycling";
  }
  return "";
}

int exit_code(Status s) {
  switch (s) {
    case Status::converged:
      return 0;
    case Status::error:
      return 2;
    case Status::not_converged:
      return 3;
    case Status::diverged:
      return 4;
    case Status::cancelled:
      return 5;
    case Status::no_bite:
      return 6;
  }
  return 1;
}

}  // namespace rollsim
