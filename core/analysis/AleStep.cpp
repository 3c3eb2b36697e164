#include "analysis/AleStep.h"

#include <algorithm>
#include <stdexcept>

#include "analysis/AnalysisError.h"
#include "material/Material.h"

namespace rollsim {

std::vector<double> advected_points(const Mesh& from, const std::vector<Point3>& x, const std::vector<double>& values,
                                    int width, const Mesh& to, const MeshMotion& motion) {
  std::vector<double> out = transfer_points(from, x, values, width, to);
  const std::vector<Point3> at = integration_points(to);
  for (size_t i = 0; i < at.size(); ++i)
    if (motion.inflow(at[i], x))
      std::fill(out.begin() + static_cast<long>(i * width), out.begin() + static_cast<long>((i + 1) * width), 0.0);
  return out;
}

AleRemap ale_remap(const Body& body, const Eigen::VectorXd& u, const std::vector<double>& committed,
                   const std::vector<MeshMotion::Positions>& current, const MeshMotion& motion) {
  const std::vector<Point3>& x = current[static_cast<size_t>(motion.body())];
  Mesh placed = body.mesh;
  placed.nodes = motion.placed(current);
  try {
    check_element_orientation(placed);
  } catch (const std::runtime_error& e) {
    throw AnalysisError("the mesh of body '" + body.name + "' put back in place would fold an element (" + e.what() +
                        ")");
  }
  AleRemap r;
  const int width = make_material(body.material)->state_size();
  if (width > 0) r.state = advected_points(body.mesh, x, current_state(body, u, committed), width, placed, motion);
  r.nodes = std::move(placed.nodes);
  return r;
}

}  // namespace rollsim
