#include "io/ConvergenceCsv.h"

#include <sstream>

namespace rollsim {

std::string convergence_csv(const Results& results) {
  std::ostringstream out;
  out.precision(10);
  out << "increment,attempt,iteration,load_factor,residual,relative_residual,correction,step_length,"
         "refactored_groups,contact_changes,cg_iterations,tangents\n";
  for (const NewtonIteration& it : results.newton)
    out << it.increment << ',' << it.attempt << ',' << it.iteration << ',' << it.load_factor << ',' << it.residual
        << ',' << it.relative << ',' << it.correction << ',' << it.step_length << ',' << it.refactored << ','
        << it.contact_changes << ',' << it.cg_iterations << ",\"" << it.tangents << "\"\n";
  return out.str();
}

}  // namespace rollsim
