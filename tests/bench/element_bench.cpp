// The Newton element kernel on its own (issue 35, item 1; docs/BENCHMARKS.md "Element kernels"): µs per element of
// the finite-strain F-bar J2 hexahedron and plane-strain quadrilateral, tangent and force, at an elastic and at a
// plastic state, on 1 and 2 threads, beside a flop count of the kernel's loops and the machine's DGEMM rate (the
// roofline's roof for dense arithmetic). Run by hand, never by ctest:
//   rollsim_element_bench [--repeat N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "../core/partition/PartitionFixtures.h"
#include "analysis/GroupLayout.h"
#include "base/DgemmPeak.h"

using namespace rollsim;

namespace {
/// A held finite-strain J2 block (the face x = 0 held: a floating one adds its kernel's update to the assembly).
Model block(int dim) {
  Model m = test::block_model(dim, dim == 2 ? std::array<int, 3>{80, 40, 1} : std::array<int, 3>{20, 16, 10});
  Body& b = m.bodies[0];
  b.material.E = 200e3;
  b.material.yield_stress = 250;
  b.material.hardening_modulus = 2000;
  b.kinematics = Kinematics::Finite;
  b.formulation = Formulation::BBar;
  test::support(m, test::nodes_in_box(m, {0, 0, 0}, {0, 1e9, 1e9}));
  return m;
}

/// Flops of one element's tangent and force, counted from the kernel's loops (FiniteStrainElement, KirchhoffModulus;
/// the eigen-decomposition and the return mapping left out): per point the deformation gradient, the modulus's
/// columns (two 3 × 3 products and a 6 × 6 one each), δτ per dof, the material term gᵀ δτ and the geometric term.
double kernel_flops(int D) {
  const double NN = D == 2 ? 4 : 8, NGP = NN, ND = NN * D;
  const double F = 2 * NN * D * D, modulus = D * D * (2 * 2 * 27 + 2 * 36 + 27);
  const double dtau = ND * (2 * 9 * D + 18), material = D * NN * ND * D * 2, geometric = 2 * ND * ND + 2 * D * D * NN;
  const double force = 2 * NN * D * D;
  return NGP * (F + modulus + dtau + material + geometric + force) + 2 * ND * ND;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// Median seconds of one Newton assembly (tangent and force) of the block at the displacement `stretch` × x.
double assembly_seconds(const Model& m, double stretch, int threads, int repeat) {
  GroupLayout layout(m, false, Multipliers::NonRedundant);
  BlockSystem& sys = layout.system();
  const Mesh& mesh = m.bodies[0].mesh;
  Eigen::VectorXd all = Eigen::VectorXd::Zero(mesh.dim * mesh.num_nodes());
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    all[mesh.dim * n] = stretch * mesh.nodes[n][0];
    all[mesh.dim * n + 1] = -0.5 * stretch * mesh.nodes[n][1];
  }
  const std::vector<Eigen::VectorXd> u{layout.body_dofs()[0]->restrict_to_free(all)};
  layout.assembler().set_threads(threads);
  const std::vector<size_t> groups = all_groups(sys);
  std::vector<double> times;
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    layout.assembler().assemble_newton(groups, groups, u, {1.0, 1.0, 0.0}, sys);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return median(times);
}
}  // namespace

int main(int argc, char** argv) {
  int repeat = 9;
  for (int i = 1; i + 1 < argc; ++i)
    if (!std::strcmp(argv[i], "--repeat")) repeat = std::max(1, std::atoi(argv[i + 1]));
  const double peak = measure_dgemm_peak(1, 256).gflops;
  std::printf("DGEMM peak, 1 thread: %.1f GFlop/s\n\n", peak);
  std::printf(
      "| element | state | elements | kernel flops / element | µs / element, 1 thread | GFlop/s | %% of DGEMM "
      "peak | 2 threads / 1 |\n|---|---|---|---|---|---|---|---|\n");
  for (int dim : {2, 3}) {
    const Model m = block(dim);
    const int n = m.bodies[0].mesh.num_elements();
    for (const auto& [state, stretch] : {std::pair{"elastic", 1e-4}, std::pair{"plastic", 2e-2}}) {
      const double one = assembly_seconds(m, stretch, 1, repeat), two = assembly_seconds(m, stretch, 2, repeat);
      const double us = 1e6 * one / n, flops = kernel_flops(dim), rate = flops / (us * 1e3);
      std::printf("| %s | %s | %d | %.0f | %.2f | %.2f | %.1f | %.3f |\n",
                  dim == 2 ? "quad, plane strain" : "hexahedron", state, n, flops, us, rate, 100 * rate / peak,
                  two / one);
    }
  }
}
