#include "project/RemeshProject.h"

#include <string>

namespace rollsim {

namespace {
std::string at(const char* list, size_t i) { return std::string(list) + "[" + std::to_string(i) + "]"; }
}  // namespace

void check_remesh(const json& expanded, int dim, std::vector<Issue>& issues) {
  const auto a = expanded.find("analysis");
  if (a == expanded.end() || a->value("remesh_quality", 0.0) <= 0.0) return;
  const std::string why = "analysis.remesh_quality";
  if (dim != 2) {
    issues.push_back({why, "only 2D quad meshes can be remeshed yet: remove it, or model the part in 2D"});
    return;
  }
  const json& bodies = expanded.at("bodies");
  for (size_t b = 0; b < bodies.size(); ++b)
    if (bodies[b].value("kinematics", "small") != "finite")
      issues.push_back({at("bodies", b) + ".kinematics",
                        "body '" + bodies[b].value("name", "") +
                            "' is small-strain: a remesh restarts every body from its current shape, which carries "
                            "a body's stress only at finite strain (its elastic strain b_e as its state): make it "
                            "'finite', or remove analysis.remesh_quality"});
  const json& conditions = expanded.at("boundary_conditions");
  for (size_t i = 0; i < conditions.size(); ++i) {
    const std::string type = conditions[i].value("type", "");
    if (type == "force" || type == "pressure" || type == "traction" || type == "body_force")
      issues.push_back({at("boundary_conditions", i),
                        "a " + type +
                            " load cannot be carried across a remesh yet (each segment starts from its "
                            "current shape with what is left of the prescribed motion): drive the run by prescribed "
                            "displacements, or remove analysis.remesh_quality"});
  }
}

}  // namespace rollsim
