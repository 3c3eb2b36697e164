// rollsim_factor_bench — issue 14: the sparse factorizations side by side on the same assembled stiffness matrices
// (body 0 of each sample), against the DGEMM rate of the same machine:
//   - rollsim's own: `cholmod` (CholmodFactorization with rollsim's settings), `skyline` (the paper's baseline);
//   - CHOLMOD variants: `cholmod:ordering=auto|automatic|amd|metis|nesdis|nodes,nrelax=A/B/C,zrelax=a/b/c`
//     (defaults: rollsim's; `cholmod-defaults` is CHOLMOD's own choice of ordering, the state before issue 14);
//   - peers: `eigen-ldlt` (Eigen's SimplicialLDLT, AMD), `mumps` (MUMPS 5.5 through MPI on one rank, METIS ordering;
//     only when the build found MUMPS).
// Per variant: analyze / factorize / solve seconds (medians of --repeat; a variant stops repeating after 10 s), the
// factorization's CPU seconds (all threads), nnz(L), flops (each solver's own count),
// GFlop/s = flops / factorize and its share of the DGEMM peak, max |u − u_ref| / max |u_ref| against the first
// variant. Markdown on stdout, progress on stderr. Timing is not a test: it fails only when a solution differs
// from the first variant's by more than 1e-8.
// Usage: rollsim_factor_bench [--repeat N] [--threads T] [--variants v1;v2;...] samples...
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <Eigen/SparseCholesky>

#include "base/Blas.h"
#include "base/DgemmPeak.h"
#include "base/Stopwatch.h"
#include "fem/Assembler.h"
#include "fem/Loads.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "solve/CholmodFactorization.h"
#include "solve/Factorization.h"

#ifdef ROLLSIM_BENCH_MUMPS
#include <dmumps_c.h>
#include <mpi.h>
#endif

namespace rollsim::bench {
namespace {

/// CPU seconds (user + system) of every thread of the process so far: what a factorization costs the machine,
/// less sensitive than wall time to other jobs on a shared machine.
double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// Eigen's SimplicialLDLT (AMD ordering) behind the Factorization interface, flops counted from L's columns as
/// CHOLMOD counts them (Σ c_j², c_j the entries of column j with the diagonal).
class EigenLdlt final : public Factorization {
 public:
  void analyze(const SparseMatrix& A) override {
    Stopwatch t;
    ldlt_.analyzePattern(A);
    stats_.analyze_s += t.seconds();
    stats_.ordering = "AMD";
  }
  void factorize(const SparseMatrix& A) override {
    Stopwatch t;
    ldlt_.factorize(A);
    stats_.factorize_s += t.seconds();
    ++stats_.factorizations;
    if (ldlt_.info() != Eigen::Success) throw SingularMatrix("Eigen SimplicialLDLT failed", -1);
    const auto& L = ldlt_.matrixL().nestedExpression();
    stats_.flops = 0;
    for (int j = 0; j < L.outerSize(); ++j) {
      const double c = L.outerIndexPtr()[j + 1] - L.outerIndexPtr()[j] + 1.0;
      stats_.flops += c * c;
    }
    stats_.nnz_factor = static_cast<double>(L.nonZeros() + L.cols());
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override {
    Stopwatch t;
    Eigen::VectorXd x = ldlt_.solve(b);
    stats_.solve_s += t.seconds();
    return x;
  }
  const FactorStats& stats() const override { return stats_; }

 private:
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;
  FactorStats stats_;
};

#ifdef ROLLSIM_BENCH_MUMPS
/// MUMPS (symmetric positive definite, centralized assembled input, one MPI rank), METIS ordering.
class Mumps final : public Factorization {
 public:
  Mumps() {
    id_.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_WORLD));
    id_.par = 1;
    id_.sym = 1;
    id_.job = -1;
    dmumps_c(&id_);
    id_.icntl[0] = id_.icntl[1] = id_.icntl[2] = -1;  // no output
    id_.icntl[3] = 0;
    id_.icntl[6] = 5;  // ICNTL(7) = 5: METIS
  }
  ~Mumps() override {
    id_.job = -2;
    dmumps_c(&id_);
  }
  Mumps(const Mumps&) = delete;
  Mumps& operator=(const Mumps&) = delete;
  void analyze(const SparseMatrix& A) override {
    Stopwatch t;
    set_values(A);
    id_.n = static_cast<MUMPS_INT>(A.rows());
    id_.nnz = static_cast<MUMPS_INT8>(irn_.size());
    id_.irn = irn_.data();
    id_.jcn = jcn_.data();
    id_.a = a_.data();
    run(1);
    stats_.analyze_s += t.seconds();
    stats_.ordering = "METIS";
  }
  void factorize(const SparseMatrix& A) override {
    Stopwatch t;
    set_values(A);
    run(2);
    stats_.factorize_s += t.seconds();
    ++stats_.factorizations;
    stats_.flops = id_.rinfog[2];                            // RINFOG(3): flops of the elimination
    stats_.nnz_factor = static_cast<double>(id_.infog[28]);  // INFOG(29): entries in the factors
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override {
    Stopwatch t;
    Eigen::VectorXd x = b;
    id_.rhs = x.data();
    id_.nrhs = 1;
    id_.lrhs = static_cast<MUMPS_INT>(x.size());
    run(3);
    stats_.solve_s += t.seconds();
    return x;
  }
  const FactorStats& stats() const override { return stats_; }

 private:
  void set_values(const SparseMatrix& A) {  // lower triangle, 1-based
    irn_.clear(), jcn_.clear(), a_.clear();
    for (int j = 0; j < A.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it)
        if (it.row() >= j) {
          irn_.push_back(static_cast<MUMPS_INT>(it.row() + 1));
          jcn_.push_back(static_cast<MUMPS_INT>(j + 1));
          a_.push_back(it.value());
        }
    id_.a = a_.data();
  }
  void run(int job) {
    id_.job = job;
    dmumps_c(&id_);
    if (id_.infog[0] < 0)
      throw std::runtime_error("MUMPS job " + std::to_string(job) +
                               " failed, INFOG(1) = " + std::to_string(id_.infog[0]));
  }
  DMUMPS_STRUC_C id_{};
  std::vector<MUMPS_INT> irn_, jcn_;
  std::vector<double> a_;
  FactorStats stats_;
};
#endif

/// "cholmod:ordering=nodes,nrelax=4/16/48,zrelax=0.8/0.1/0.05" (every key optional; the defaults are rollsim's).
CholmodSettings parse_cholmod(const std::string& spec) {
  CholmodSettings s;
  const auto colon = spec.find(':');
  if (colon == std::string::npos) return s;
  std::stringstream items(spec.substr(colon + 1));
  std::string item;
  while (std::getline(items, item, ',')) {
    const auto eq = item.find('=');
    const std::string key = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
    std::stringstream parts(value);
    std::string part;
    if (key == "ordering") {
      s.ordering = value;
    } else if (key == "nrelax") {
      for (int i = 0; i < 3 && std::getline(parts, part, '/'); ++i) s.nrelax[i] = std::stoi(part);
    } else if (key == "zrelax") {
      for (int i = 0; i < 3 && std::getline(parts, part, '/'); ++i) s.zrelax[i] = std::stod(part);
    } else {
      throw std::invalid_argument("unknown CHOLMOD setting '" + key + "' in " + spec);
    }
  }
  return s;
}

std::unique_ptr<Factorization> make_variant(const std::string& name) {
  if (name == "cholmod-defaults") return std::make_unique<CholmodFactorization>(CholmodSettings::cholmod_defaults());
  if (name.rfind("cholmod:", 0) == 0) return std::make_unique<CholmodFactorization>(parse_cholmod(name));
  if (name == "eigen-ldlt") return std::make_unique<EigenLdlt>();
#ifdef ROLLSIM_BENCH_MUMPS
  if (name == "mumps") return std::make_unique<Mumps>();
#endif
  return make_factorization(name);  // cholmod, skyline
}

struct Row {
  std::string sample, variant, ordering;
  long dofs = 0;
  double nnz = 0, flops = 0, analyze = 0, factorize = 0, factorize_cpu = 0, solve = 0, diff = 0;
};

Row measure(const std::string& sample, const std::string& variant, const SparseMatrix& K, const Eigen::VectorXd& f,
            int repeat, Eigen::VectorXd& u) {
  Row row{sample, variant, "", K.rows()};
  std::vector<double> analyze, factorize, factorize_cpu, solve;
  Stopwatch spent;
  for (int r = 0; r < repeat && (r == 0 || spent.seconds() < 10); ++r) {  // a slow peer: fewer repeats
    auto factor = make_variant(variant);
    factor->analyze(K);
    const double cpu0 = cpu_seconds();
    factor->factorize(K);
    factorize_cpu.push_back(cpu_seconds() - cpu0);
    u = factor->solve(f);
    const FactorStats& st = factor->stats();
    analyze.push_back(st.analyze_s);
    factorize.push_back(st.factorize_s);
    solve.push_back(st.solve_s);
    row.ordering = st.ordering;
    row.nnz = st.nnz_factor;
    row.flops = st.flops;
  }
  row.analyze = median(analyze);
  row.factorize = median(factorize);
  row.factorize_cpu = median(factorize_cpu);
  row.solve = median(solve);
  return row;
}

int run(int argc, char** argv) {
  int repeat = 3, threads = 1;
  std::string variants = "cholmod-defaults;cholmod;skyline;eigen-ldlt";
#ifdef ROLLSIM_BENCH_MUMPS
  variants += ";mumps";
#endif
  std::vector<std::string> samples;
  CLI::App app{"factorizations side by side on the samples' stiffness matrices (issue 14)"};
  app.add_option("--repeat", repeat, "repetitions (medians)")->check(CLI::Range(1, 100));
  app.add_option("--threads", threads, "BLAS threads")->check(CLI::Range(1, 64));
  app.add_option("--variants", variants, "variants separated by ';' (the first is the reference)");
  app.add_option("samples", samples, "project files")->required();
  CLI11_PARSE(app, argc, argv);
  set_library_threads(threads);
  const DgemmPeak peak = measure_dgemm_peak(threads, 0, 40, 0.5);
  std::printf("DGEMM peak (%d thread(s), n = %d, best of %d calls): %.1f GFlop/s\n\n", threads, peak.n, peak.calls,
              peak.gflops);
  std::printf(
      "| sample | variant | ordering | dofs | nnz(L) | flops | analyze s | factorize s | factorize CPU s | solve s | "
      "GFlop/s | %% of peak | max diff |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> names;
  std::stringstream list(variants);
  for (std::string v; std::getline(list, v, ';');)
    if (!v.empty()) names.push_back(v);
  bool ok = true;
  bool warm = false;
  for (const auto& file : samples) {
    const Model model = build_model(load_project(file));
    const Body& body = model.bodies[0];
    DofMap dofs(body, 0, model.displacements);
    Assembler assembler(body, dofs);
    SparseMatrix K;
    Eigen::VectorXd f;
    assembler.assemble(K, f);
    f += dofs.restrict_to_free(external_nodal_load(model, 0));
    const std::string sample = std::filesystem::path(file).stem().string();
    Eigen::VectorXd u_ref;
    if (!warm) {  // the process's first factorization pays for fresh pages and the BLAS's buffers: not timed
      Eigen::VectorXd u;
      measure(sample, "cholmod", K, f, 1, u);
      warm = true;
    }
    for (size_t i = 0; i < names.size(); ++i) {
      Eigen::VectorXd u;
      Row r = measure(sample, names[i], K, f, repeat, u);
      if (i == 0) u_ref = u;
      r.diff = (u - u_ref).cwiseAbs().maxCoeff() / u_ref.cwiseAbs().maxCoeff();
      ok = ok && r.diff < 1e-8;
      const double rate = gflops(r.flops, r.factorize);
      std::printf("| %s | %s | %s | %ld | %.3g | %.3g | %.4f | %.4f | %.4f | %.4f | %.2f | %.1f %% | %.1e |\n",
                  r.sample.c_str(), r.variant.c_str(), r.ordering.c_str(), r.dofs, r.nnz, r.flops, r.analyze,
                  r.factorize, r.factorize_cpu, r.solve, rate, 100 * rate / peak.gflops, r.diff);
      std::fflush(stdout);
      std::fprintf(stderr, "factor_bench: %s %s done\n", sample.c_str(), names[i].c_str());
    }
  }
  return ok ? 0 : 1;
}

}  // namespace
}  // namespace rollsim::bench

int main(int argc, char** argv) {
#ifdef ROLLSIM_BENCH_MUMPS
  MPI_Init(&argc, &argv);
#endif
  int rc = 1;
  try {
    rc = rollsim::bench::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "factor_bench: error: %s\n", e.what());
  }
#ifdef ROLLSIM_BENCH_MUMPS
  MPI_Finalize();
#endif
  return rc;
}
