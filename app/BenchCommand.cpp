// `rollsim bench`: per-stage times (pattern, values, analyze, factorize, solve) of `skyline` vs
// CHOLMOD on the same assembled systems, medians of repeated runs, factor size and flops, and the factorizations'
// rate against the DGEMM peak measured in the same process (issue 14).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "Commands.h"
#include "base/Blas.h"
#include "base/DgemmPeak.h"
#include "base/Stopwatch.h"
#include "fem/Assembler.h"
#include "fem/Loads.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "solve/Factorization.h"
#include "solve/SkylineFactorization.h"

namespace rollsim::app {

namespace {

struct StageTimes {
  double pattern = 0, values = 0, analyze = 0, factorize = 0, solve = 0;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Row {
  std::string sample, solver, ordering;
  long dofs = 0;
  double nnz = 0, flops = 0, counted_flops = -1;  // counted: skyline only
  StageTimes t;
  double max_rel_diff = 0;
};

/// One repetition: assemble body 0 and factor/solve with `kind`; returns the solution.
Eigen::VectorXd run_once(const Model& model, const std::string& kind, StageTimes& t, Row& row) {
  const Body& body = model.bodies[0];
  DofMap dofs(body, 0, model.displacements);
  Stopwatch sp;
  Assembler assembler(body, dofs);
  t.pattern = sp.seconds();
  SparseMatrix K;
  Eigen::VectorXd f;
  Stopwatch sv;
  assembler.assemble(K, f);
  t.values = sv.seconds();
  f += dofs.restrict_to_free(external_nodal_load(model, 0));
  auto factor = make_factorization(kind);
  factor->analyze(K);
  factor->factorize(K);
  const Eigen::VectorXd u = factor->solve(f);
  const FactorStats& st = factor->stats();
  t.analyze = st.analyze_s;
  t.factorize = st.factorize_s;
  t.solve = st.solve_s;
  row.ordering = st.ordering;
  row.nnz = st.nnz_factor;
  row.flops = st.flops;
  if (const auto* sky = dynamic_cast<const SkylineFactorization*>(factor.get()))
    row.counted_flops = sky->counted_flops();
  row.dofs = K.rows();
  return u;
}

Row bench(const std::string& file, const Model& model, const std::string& kind, int repeat, Eigen::VectorXd& u) {
  Row row;
  row.sample = std::filesystem::path(file).stem().string();
  row.solver = kind;
  std::vector<StageTimes> runs(static_cast<size_t>(repeat));
  for (auto& t : runs) u = run_once(model, kind, t, row);
  auto med = [&](double StageTimes::*m) {
    std::vector<double> v;
    for (const auto& t : runs) v.push_back(t.*m);
    return median(v);
  };
  row.t = {med(&StageTimes::pattern), med(&StageTimes::values), med(&StageTimes::analyze), med(&StageTimes::factorize),
           med(&StageTimes::solve)};
  return row;
}

std::string short_ordering(const Row& r) { return r.ordering.substr(0, r.ordering.find(' ')); }

std::string counted(const Row& r) {
  char buf[32];
  if (r.counted_flops < 0) return "-";
  std::snprintf(buf, sizeof buf, "%.17g", r.counted_flops);
  return buf;
}

void print_table(const std::vector<Row>& rows, double peak) {
  std::printf("DGEMM peak: %.2f GFlop/s\n", peak);
  std::printf("%-24s %-8s %6s %-11s %10s %10s %10s %8s %8s %8s %9s %8s %9s %7s %6s\n", "sample", "solver", "dofs",
              "ordering", "nnz(L)", "flops", "counted", "pattern", "values", "analyze", "factorize", "solve",
              "max diff", "GFlop/s", "%peak");
  for (const Row& r : rows) {
    char count[32] = "-";
    if (r.counted_flops >= 0) std::snprintf(count, sizeof count, "%.4g", r.counted_flops);
    const double rate = gflops(r.flops, r.t.factorize);
    std::printf("%-24s %-8s %6ld %-11s %10.4g %10.4g %10s %8.4f %8.4f %8.4f %9.4f %8.4f %9.2e %7.2f %5.1f%%\n",
                r.sample.c_str(), r.solver.c_str(), r.dofs, short_ordering(r).c_str(), r.nnz, r.flops, count,
                r.t.pattern, r.t.values, r.t.analyze, r.t.factorize, r.t.solve, r.max_rel_diff, rate,
                peak > 0 ? 100 * rate / peak : 0.0);
  }
}

bool write_csv(const std::string& file, const std::vector<Row>& rows, double peak) {
  std::ofstream csv(file);
  csv << "sample,solver,dofs,ordering,nnz_factor,flops,counted_flops,pattern_s,values_s,analyze_s,factorize_s,"
         "solve_s,max_rel_diff,factor_gflops,dgemm_peak_gflops\n";
  csv.precision(17);
  for (const Row& r : rows)
    csv << r.sample << "," << r.solver << "," << r.dofs << "," << short_ordering(r) << "," << r.nnz << "," << r.flops
        << "," << counted(r) << "," << r.t.pattern << "," << r.t.values << "," << r.t.analyze << "," << r.t.factorize
        << "," << r.t.solve << "," << r.max_rel_diff << "," << gflops(r.flops, r.t.factorize) << "," << peak << "\n";
  return static_cast<bool>(csv);
}

/// The two invariants of the comparison: skyline counted flops == predicted, solutions equal to 1e-10.
bool consistent(const std::vector<Row>& rows) {
  bool ok = true;
  for (const Row& r : rows) {
    if (r.counted_flops >= 0 && r.counted_flops != r.flops) {
      std::fprintf(stderr, "rollsim: bench %s: counted flops %.17g != predicted %.17g\n", r.sample.c_str(),
                   r.counted_flops, r.flops);
      ok = false;
    }
    if (!(r.max_rel_diff < 1e-10)) {
      std::fprintf(stderr, "rollsim: bench %s: skyline and CHOLMOD differ by %.3e\n", r.sample.c_str(), r.max_rel_diff);
      ok = false;
    }
  }
  return ok;
}

}  // namespace

int bench_command(const BenchOptions& o) {
  set_library_threads(o.threads);
  const double peak = measure_dgemm_peak(o.threads, 0, 40, 0.5).gflops;  // before the samples: nothing to disturb
  std::vector<Row> rows;
  for (const auto& file : o.samples) {
    Model model;
    try {
      model = build_model(load_project(file));
    } catch (const ProjectError& e) {
      std::fprintf(stderr, "rollsim: error: %s\n", e.what());
      return 2;
    }
    Eigen::VectorXd u_sky, u_chol;
    rows.push_back(bench(file, model, "skyline", o.repeat, u_sky));
    rows.push_back(bench(file, model, "cholmod", o.repeat, u_chol));
    const double diff = (u_sky - u_chol).cwiseAbs().maxCoeff() / u_chol.cwiseAbs().maxCoeff();
    rows[rows.size() - 1].max_rel_diff = rows[rows.size() - 2].max_rel_diff = diff;
    std::fprintf(stderr, "rollsim: bench %s done\n", file.c_str());
  }
  print_table(rows, peak);
  if (!o.csv.empty() && !write_csv(o.csv, rows, peak)) {
    std::fprintf(stderr, "rollsim: error: cannot write %s\n", o.csv.c_str());
    return 2;
  }
  return consistent(rows) ? 0 : 1;
}

}  // namespace rollsim::app
