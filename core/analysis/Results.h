#pragma once
// Fields and scalars produced by an analysis, per body; read by the writers.
#include <Eigen/Dense>
#include <array>
#include <map>
#include <string>
#include <vector>

namespace rollsim {

struct BodyResults {
  Eigen::VectorXd displacement;  // node-major, dim components per node [length]
  Eigen::VectorXd nodal_force;   // internal minus external force at every dof: reactions at supports [force]
  std::vector<std::array<double, 6>> element_stress;  // element mean (xx, yy, zz, xy, yz, zx) [stress]
  std::vector<std::array<double, 6>> nodal_stress;    // extrapolated from Gauss points, averaged at nodes
  std::vector<int> subdomain;                         // per element (0 while bodies are not partitioned)
};

struct Timing {
  double total_s = 0, stiffness_s = 0, analyze_s = 0, factorize_s = 0, solve_s = 0, recovery_s = 0;
};

struct Results {
  std::string status = "converged";  // converged / diverged / cancelled / error
  std::vector<BodyResults> bodies;
  long dofs = 0;
  Timing timing;
};

}  // namespace rollsim
