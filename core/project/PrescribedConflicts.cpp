#include "project/PrescribedConflicts.h"

#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>

#include "model/PrescribedMotion.h"

namespace rollsim {

namespace {
std::string path_of(int source) { return "boundary_conditions[" + std::to_string(source) + "]"; }

std::string number(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.9g", v);
  return s;
}
}  // namespace

std::vector<Issue> prescribed_conflicts(const Model& model) {
  std::vector<Issue> issues;
  // (body, node, component) -> (value, index into model.displacements) of the first condition that set it
  std::map<std::tuple<int, int, int>, std::pair<double, size_t>> first;
  std::set<std::pair<size_t, size_t>> reported;
  for (size_t i = 0; i < model.displacements.size(); ++i) {
    const DisplacementBC& d = model.displacements[i];
    const Mesh& mesh = model.bodies[static_cast<size_t>(d.body)].mesh;
    for (int c = 0; c < model.dim; ++c) {
      for (int n : d.nodes) {
        const auto& x = mesh.nodes[static_cast<size_t>(n)];
        const std::optional<double> v = prescribed_value(d, x, c, 1.0);
        if (!v) continue;
        const auto [it, inserted] = first.try_emplace({d.body, n, c}, *v, i);
        if (inserted || it->second.first == *v || !reported.insert({it->second.second, i}).second) continue;
        const DisplacementBC& other = model.displacements[it->second.second];
        issues.push_back({path_of(d.source), "prescribes u" + std::string(1, "xyz"[c]) + " = " + number(*v) +
                                                 " at node " + std::to_string(n) + " (" + number(x[0]) + ", " +
                                                 number(x[1]) + (model.dim == 3 ? ", " + number(x[2]) : "") +
                                                 ") of body '" + model.bodies[static_cast<size_t>(d.body)].name +
                                                 "', which " + path_of(other.source) + " prescribes as " +
                                                 number(it->second.first) +
                                                 ": remove one of the two conditions or make them agree"});
      }
    }
  }
  return issues;
}

}  // namespace rollsim
