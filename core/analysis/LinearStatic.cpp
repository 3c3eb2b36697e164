#include "analysis/LinearStatic.h"

#include <memory>

#include "analysis/Recovery.h"
#include "fem/Assembler.h"
#include "fem/Loads.h"
#include "model/DofMap.h"
#include "solve/Stopwatch.h"

namespace rollsim {

namespace {
// Names the body, node and component of global equation `col` (groups stacked in order).
std::string describe_singular(const Model& model, const std::vector<std::unique_ptr<DofMap>>& dofs, int col) {
  std::string where;
  int offset = 0;
  for (size_t b = 0; b < dofs.size() && where.empty(); ++b) {
    const DofMap& d = *dofs[b];
    if (col >= offset && col < offset + d.num_free()) {
      const Mesh& m = model.bodies[b].mesh;
      for (int n = 0; n < m.num_nodes() && where.empty(); ++n)
        for (int c = 0; c < m.dim; ++c)
          if (d.equation(n, c) == col - offset) {
            const auto& x = m.nodes[n];
            where = " at body '" + model.bodies[b].name + "', node " + std::to_string(n) + " (" + std::to_string(x[0]) +
                    ", " + std::to_string(x[1]) + (m.dim == 3 ? ", " + std::to_string(x[2]) : "") + "), component " +
                    "xyz"[c];
          }
    }
    offset += d.num_free();
  }
  return "the stiffness matrix is singular" + where +
         ": a body is not held against rigid-body motion (add displacement or symmetry conditions)";
}
}  // namespace

Results run_linear_static(const Model& model, SolverStrategy& solver, AnalysisObserver* observer) {
  AnalysisObserver quiet;
  AnalysisObserver& obs = observer ? *observer : quiet;
  Stopwatch total;
  Results res;
  std::vector<std::unique_ptr<DofMap>> dofs;
  BlockSystem sys;
  obs.on_stage("assemble");
  Stopwatch t;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    dofs.push_back(std::make_unique<DofMap>(body, static_cast<int>(b), model.displacements));
    Group g;
    g.name = body.name;
    g.body = static_cast<int>(b);
    Assembler assembler(body, *dofs.back());
    assembler.assemble(g.K, g.f);
    g.f += dofs.back()->restrict_to_free(external_nodal_load(model, static_cast<int>(b)));
    res.dofs += g.K.rows();
    sys.groups.push_back(std::move(g));
  }
  res.timing.stiffness_s = t.seconds();
  if (obs.cancel_requested()) {
    res.status = "cancelled";
    return res;
  }
  obs.on_stage("solve");
  BlockSolution sol;
  try {
    sol = solver.solve(sys, &obs);
  } catch (const SingularMatrix& e) {
    throw UnsupportedBody(describe_singular(model, dofs, e.column));
  }
  const SolveStats& st = solver.stats();
  res.timing.analyze_s = st.analyze_s;
  res.timing.factorize_s = st.factorize_s;
  res.timing.solve_s = st.solve_s;
  obs.on_stage("recover");
  Stopwatch tr;
  for (size_t b = 0; b < model.bodies.size(); ++b)
    res.bodies.push_back(recover(model, static_cast<int>(b), dofs[b]->expand(sol.u[b])));
  res.timing.recovery_s = tr.seconds();
  res.timing.total_s = total.seconds();
  return res;
}

}  // namespace rollsim
