// rollsim_partition_report_bench — the core half of the GUI's live partition table (issue 6, item 3): how long
// PartitionReporter takes for the first report of a body and for the update after a paint stroke that moves
// ~500 cells from one subdomain to a neighbouring one (grown breadth first from a random cell on their interface,
// then painted back by the next stroke). Target: well under 100 ms per stroke (the GUI's budget for a whole
// stroke, rendering included). Markdown on stdout, progress on stderr; nothing here fails on a slow machine.
// A second section compares the factor estimate with CHOLMOD's own analysis of the assembled stiffness.
// Usage: rollsim_partition_report_bench [--sections timing,cholmod] [--repeat N] [--size NXxNYxNZ] [--cells N]
//                                       [--threads 1,2]
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "fem/Assembler.h"
#include "mesh/StructuredBlock.h"
#include "model/DofMap.h"
#include "partition/DualGraph.h"
#include "partition/MetisPartition.h"
#include "partition/PartitionReport.h"
#include "partition/StructuredPartition.h"
#include "partition/Subdomain.h"
#include "solve/CholmodFactorization.h"

namespace rollsim::bench {
namespace {

struct Options {
  std::set<std::string> sections{"timing", "cholmod"};
  int repeat = 21;
  std::array<int, 3> size{100, 50, 20};
  int cells = 500;
  std::vector<int> threads{1, 2};
};

void progress(const std::string& s) { std::cerr << "partition_report_bench: " << s << std::endl; }

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

/// CPU time of the process (every thread), for a machine shared with other jobs.
double process_cpu_ms() { return 1e3 * static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

std::vector<int> parse_list(const std::string& text, char sep) {
  std::vector<int> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, sep);) out.push_back(std::stoi(item));
  return out;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--repeat") o.repeat = std::stoi(value);
    if (key == "--cells") o.cells = std::stoi(value);
    if (key == "--threads") o.threads = parse_list(value, ',');
    if (key == "--sections") {
      o.sections.clear();
      std::stringstream in(value);
      for (std::string item; std::getline(in, item, ',');) o.sections.insert(item);
    }
    if (key == "--size") {
      const std::vector<int> n = parse_list(value, 'x');
      for (size_t a = 0; a < 3 && a < n.size(); ++a) o.size[a] = n[a];
    }
  }
  return o;
}

/// A unit-cell block clamped at x = 0 (2D: nz ignored).
struct Slab {
  Body body;
  std::vector<DisplacementBC> bcs;
};

Slab make_slab(const std::array<int, 3>& n, int dim = 3) {
  Slab s;
  BlockSpec spec;
  spec.dim = dim;
  spec.n = n;
  spec.size = {double(n[0]), double(n[1]), double(n[2])};
  s.body.name = "slab";
  s.body.mesh = make_block(spec);
  s.body.material.E = 210e3;
  s.body.material.nu = 0.3;
  DisplacementBC clamp;
  clamp.nodes = s.body.mesh.node_sets.at("xmin");
  for (int c = 0; c < dim; ++c) clamp.value[c] = 0.0;
  s.bcs.push_back(clamp);
  return s;
}

/// `count` cells of the subdomain of a random cell on an interface, grown breadth first from it; and the
/// neighbouring subdomain they are painted into.
struct Stroke {
  std::vector<int> cells;
  int from = 0, to = 0;
};

Stroke random_stroke(const DualGraph& g, const std::vector<int>& map, int count, std::mt19937& rng) {
  std::uniform_int_distribution<int> pick(0, static_cast<int>(map.size()) - 1);
  Stroke s;
  for (;;) {  // a cell with a neighbour in another subdomain
    const int e = pick(rng);
    for (int k = g.xadj[e]; k < g.xadj[e + 1]; ++k)
      if (map[g.adjncy[k]] != map[e]) s = {{e}, map[e], map[g.adjncy[k]]};
    if (!s.cells.empty()) break;
  }
  std::vector<char> seen(map.size(), 0);
  seen[s.cells[0]] = 1;
  for (size_t at = 0; at < s.cells.size() && static_cast<int>(s.cells.size()) < count; ++at)
    for (int k = g.xadj[s.cells[at]]; k < g.xadj[s.cells[at] + 1] && static_cast<int>(s.cells.size()) < count; ++k)
      if (const int n = g.adjncy[k]; map[n] == s.from && !seen[n]) {
        seen[n] = 1;
        s.cells.push_back(n);
      }
  return s;
}

struct Row {
  std::string partition;
  int threads = 1;
  double setup_ms = 0, first_ms = 0, median_ms = 0, max_ms = 0, cpu_ms = 0;
  double cells_moved = 0;
  int recomputed = 0;
};

Row run(const Slab& slab, const DofMap& dofs, const Partition& start, int threads, const Options& o) {
  Row row;
  row.partition = start.description;
  row.threads = threads;
  auto t0 = std::chrono::steady_clock::now();
  ReporterOptions options;
  options.threads = threads;
  PartitionReporter reporter(slab.body, dofs, options);
  row.setup_ms = ms_since(t0);
  t0 = std::chrono::steady_clock::now();
  reporter.update(start);
  row.first_ms = ms_since(t0);
  const DualGraph g = dual_graph(slab.body.mesh.num_elements(), shared_facets(slab.body.mesh));
  std::mt19937 rng(7);
  Partition p = start;
  std::vector<double> times, cpu;
  for (int k = 0; k < o.repeat; ++k) {
    const Stroke s = random_stroke(g, p.element_subdomain, o.cells, rng);
    for (int e : s.cells) p.element_subdomain[e] = s.to;
    t0 = std::chrono::steady_clock::now();
    const double c0 = process_cpu_ms();
    reporter.update(p);
    times.push_back(ms_since(t0));
    cpu.push_back(process_cpu_ms() - c0);
    row.cells_moved += static_cast<double>(s.cells.size()) / o.repeat;
    row.recomputed = std::max(row.recomputed, reporter.last_recomputed());
    for (int e : s.cells) p.element_subdomain[e] = s.from;  // the next stroke starts from the same map
    reporter.update(p);
  }
  row.median_ms = median(times);
  row.cpu_ms = median(cpu);
  row.max_ms = *std::max_element(times.begin(), times.end());
  return row;
}

void print_table(const PartitionReport& r) {
  std::printf(
      "| subdomain | elements | nodes | dofs | multipliers | paper | rigid modes | pieces | nnz(L) | flops |"
      " cost [flops] |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const SubdomainReport& x : r.subdomains)
    std::printf("| %d | %d | %d | %d | %ld | %ld | %d | %d | %.3g | %.3g | %.3g |\n", x.id, x.elements, x.nodes, x.dofs,
                x.multipliers, x.paper_multipliers, x.rigid_modes_after_split, x.pieces, x.factor.nnz, x.factor.flops,
                x.cost);
  std::printf("| Σ | %d | | %ld | %ld | %ld | %ld | | %.3g | %.3g | %.3g |\n", r.body_elements, r.dofs, r.multipliers,
              r.paper_multipliers, r.rigid_modes_after_split, r.subdomain_factors.nnz, r.subdomain_factors.flops,
              r.cost);
  std::printf(
      "| one domain | %d | | %d | | | | | %.3g | %.3g | %.3g |\n\npredicted cost ratio (partition / one "
      "domain): %.3f\n\n",
      r.body_elements, r.body_dofs, r.one_domain.nnz, r.one_domain.flops, r.one_domain_cost, r.predicted_ratio);
}

/// estimate_factor against CHOLMOD's analysis of the assembled K (its own AMD / METIS choice).
void compare_with_cholmod(const std::string& label, const Body& body, const DofMap& dofs) {
  progress("CHOLMOD comparison: " + label);
  auto t0 = std::chrono::steady_clock::now();
  const FactorEstimate ours = estimate_factor(body.mesh, dofs);
  const double ours_ms = ms_since(t0);
  SparseMatrix K;
  Eigen::VectorXd f;
  Assembler(body, dofs).assemble(K, f);
  CholmodFactorization cholmod;
  t0 = std::chrono::steady_clock::now();
  cholmod.analyze(K);
  const double cholmod_ms = ms_since(t0);
  const FactorStats& c = cholmod.stats();
  std::printf("| %s | %d | %.4g | %.4g | %s | %.2f | %.4g | %.4g | %.2f | %.0f | %.0f |\n", label.c_str(),
              dofs.num_free(), ours.nnz, c.nnz_factor, c.ordering.c_str(), ours.nnz / c.nnz_factor, ours.flops, c.flops,
              ours.flops / c.flops, ours_ms, cholmod_ms);
  std::fflush(stdout);
}

void cholmod_section(const Slab& slab, const DofMap& dofs, const Partition& p) {
  std::printf(
      "\nThe estimate (AMD on the node graph) against CHOLMOD's analysis of the assembled K (Common->lnz, "
      "Common->fl; CHOLMOD orders the dof matrix with AMD and, when AMD gives 500 flops or more per entry of L, "
      "also with METIS, keeping the smaller factor):\n\n"
      "| body | dofs | nnz(L) ours | nnz(L) CHOLMOD | CHOLMOD ordering | ratio | flops ours | flops CHOLMOD | "
      "ratio | ours [ms] | CHOLMOD analyze [ms] |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  const std::vector<Subdomain> subs = extract_subdomains(slab.body, dofs, p);
  compare_with_cholmod("3D slab, subdomain 0 of " + p.description, subs[0].body, *subs[0].dofs);
  compare_with_cholmod("3D slab, subdomain 1 of " + p.description + " (floating)", subs[1].body, *subs[1].dofs);
  compare_with_cholmod("3D slab, one domain", slab.body, dofs);
  const Slab plate = make_slab({400, 200, 1}, 2);
  const DofMap plate_dofs(plate.body, 0, plate.bcs);
  const Partition quarters = structured_partition(plate.body.mesh, {2, 2, 1});
  const std::vector<Subdomain> plate_subs = extract_subdomains(plate.body, plate_dofs, quarters);
  compare_with_cholmod("2D plate 400×200, subdomain 0 of 2x2", plate_subs[0].body, *plate_subs[0].dofs);
  compare_with_cholmod("2D plate 400×200, one domain", plate.body, plate_dofs);
}

void timing_section(const Slab& slab, const DofMap& dofs, const std::vector<Partition>& starts, const Options& o) {
  const int cells = slab.body.mesh.num_elements();
  std::printf(
      "Block %d×%d×%d (%d hexahedra, %d free dofs, clamped at x = 0), 8 subdomains; a stroke moves ~%d cells "
      "between two neighbouring subdomains; %d strokes per row (each followed by an untimed stroke painting "
      "them back).\n\n",
      o.size[0], o.size[1], o.size[2], cells, dofs.num_free(), o.cells, o.repeat);
  std::printf(
      "| start map | cells | subdomains | threads | setup [ms] | first report [ms] | cells per stroke | "
      "update median [ms] | update max [ms] | update CPU median [ms] | subdomains recomputed |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Partition& start : starts)
    for (int t : o.threads) {
      progress(start.description + ", " + std::to_string(t) + " thread(s)");
      const Row r = run(slab, dofs, start, t, o);
      std::printf("| %s | %d | %d | %d | %.0f | %.0f | %.0f | %.1f | %.1f | %.1f | %d |\n", r.partition.c_str(), cells,
                  start.num_subdomains, r.threads, r.setup_ms, r.first_ms, r.cells_moved, r.median_ms, r.max_ms,
                  r.cpu_ms, r.recomputed);
      std::fflush(stdout);
    }
  std::printf("\nThe table the GUI shows for %s:\n\n", starts[0].description.c_str());
  PartitionReporter reporter(slab.body, dofs);
  print_table(reporter.update(starts[0]));
}

int main_bench(int argc, char** argv) {
  const Options o = parse(argc, argv);
  progress("building the slab");
  const Slab slab = make_slab(o.size);
  const DofMap dofs(slab.body, 0, slab.bcs);
  const std::vector<Partition> starts{structured_partition(slab.body.mesh, {2, 2, 2}),
                                      metis_partition(slab.body.mesh, 8)};
  if (o.sections.count("timing")) timing_section(slab, dofs, starts, o);
  if (o.sections.count("cholmod")) cholmod_section(slab, dofs, starts[0]);
  return 0;
}

}  // namespace
}  // namespace rollsim::bench

int main(int argc, char** argv) { return rollsim::bench::main_bench(argc, argv); }
