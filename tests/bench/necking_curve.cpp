// The necking bar's curves (docs/VALIDATION.md, "Simo's necking bar") from `rollsim run` summaries of
// samples/necking-bar-3d.json and its variants: per converged increment the edge displacement u (the modelled end's
// axial displacement; each end of the whole bar moves u, the total elongation is 2u), the axial load on the whole bar
// (4 × the reaction on the quarter section's end) and the current radius at the neck and at the end. Writes
// necking.csv, necking_load.png and necking_radius.png into --out, and prints a markdown table of the meshes beside the
// reference points. Run by tests/bench/run_necking_benchmarks.sh, never by ctest.
//
//   rollsim_necking_curve --out DIR [--reference FILE] LABEL=summary.json ...
//
// The reference file (published or closed-form points) is CSV with a header: series,quantity,edge_displacement_mm,value
// (quantity: load_kN or neck_ratio).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "CurveCharts.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

constexpr double kRadius = 6.413, kNeckRatio = 0.982;  // mm; the sample's imperfection

struct Row {
  double edge = 0, load_kN = 0, neck_ratio = kNeckRatio, end_ratio = 1;
  int newton = 0;
};

struct Run {
  std::string label, status;
  std::vector<Row> rows;
};

Run read_run(const std::string& label, const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  const json s = json::parse(in);
  Run run{label, s.value("status", "?"), {Row{}}};
  for (const json& inc : s.at("increments")) {
    if (!inc.contains("probes")) continue;
    Row r;
    r.edge = inc["probes"]["end"][2].get<double>();
    r.load_kN = 4.0 * inc["reactions"]["bar"]["zmax"][2].get<double>() / 1000.0;
    r.neck_ratio = (kNeckRatio * kRadius + inc["probes"]["neck"][0].get<double>()) / kRadius;
    r.end_ratio = (kRadius + inc["probes"]["end"][0].get<double>()) / kRadius;
    r.newton = inc.value("newton_iterations", 0);
    run.rows.push_back(r);
  }
  return run;
}

struct Reference {
  std::string series, quantity;
  double edge, value;
};

std::vector<Reference> read_reference(const fs::path& file) {
  std::vector<Reference> out;
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream ss(line);
    Reference p;
    std::string e, v;
    std::getline(ss, p.series, ',');
    std::getline(ss, p.quantity, ',');
    std::getline(ss, e, ',');
    std::getline(ss, v, ',');
    p.edge = std::stod(e);
    p.value = std::stod(v);
    out.push_back(p);
  }
  return out;
}

/// Linear interpolation of a run's quantity at an edge displacement (NaN outside the run).
double at(const Run& run, double edge, double Row::*q) {
  for (size_t i = 1; i < run.rows.size(); ++i) {
    const Row &a = run.rows[i - 1], &b = run.rows[i];
    if (edge >= a.edge - 1e-12 && edge <= b.edge + 1e-12) {
      const double t = b.edge > a.edge ? (edge - a.edge) / (b.edge - a.edge) : 1;
      return a.*q + t * (b.*q - a.*q);
    }
  }
  return std::nan("");
}

void write_csv(const fs::path& file, const std::vector<Run>& runs) {
  std::ofstream out(file);
  out << "mesh,edge_displacement_mm,load_kN,neck_ratio,end_ratio,newton_iterations\n";
  char line[200];
  for (const Run& run : runs)
    for (const Row& r : run.rows) {
      std::snprintf(line, sizeof line, "%s,%.6g,%.6g,%.6g,%.6g,%d\n", run.label.c_str(), r.edge, r.load_kN,
                    r.neck_ratio, r.end_ratio, r.newton);
      out << line;
    }
}

void write_plots(const fs::path& dir, const std::vector<Run>& runs, const std::vector<Reference>& reference) {
  for (const auto& [quantity, member, file, title, y_title, y_min] :
       {std::tuple{"load_kN", &Row::load_kN, "necking_load.png", "Necking bar: axial load, whole bar", "load [kN]",
                   0.0},
        std::tuple{"neck_ratio", &Row::neck_ratio, "necking_radius.png",
                   "Necking bar: current radius at the neck / initial radius", "r / R0", 1.0}}) {
    std::vector<rollsim::ui::Curve> curves;
    for (const Run& run : runs) {
      rollsim::ui::Curve c{run.label, {}, false};
      for (const Row& r : run.rows) c.points.emplace_back(r.edge, r.*member);
      curves.push_back(c);
    }
    std::map<std::string, rollsim::ui::Curve> refs;
    for (const Reference& p : reference)
      if (p.quantity == quantity) {
        refs[p.series].name = p.series;
        refs[p.series].reference = true;
        refs[p.series].points.emplace_back(p.edge, p.value);
      }
    for (auto& [name, c] : refs) curves.push_back(c);
    rollsim::ui::write_curves_png(dir / file, title, "edge displacement u [mm], each end", y_title, curves, y_min);
  }
}

void print_table(const std::vector<Run>& runs, const std::vector<Reference>& reference) {
  std::printf(
      "| mesh | status | peak load [kN] | at u [mm] | load at u = 3.5 mm [kN] | r/R0 neck, u = 3.5 mm | r/R0 end | "
      "Newton iterations |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const Run& run : runs) {
    Row peak;
    int newton = 0;
    for (const Row& r : run.rows) {
      if (r.load_kN > peak.load_kN) peak = r;
      newton += r.newton;
    }
    std::printf("| %s | %s | %.2f | %.2f | %.2f | %.3f | %.3f | %d |\n", run.label.c_str(), run.status.c_str(),
                peak.load_kN, peak.edge, at(run, 3.5, &Row::load_kN), at(run, 3.5, &Row::neck_ratio),
                at(run, 3.5, &Row::end_ratio), newton);
  }
  if (reference.empty()) return;
  std::printf("\n| reference | quantity | u [mm] | value |");
  for (const Run& run : runs) std::printf(" %s |", run.label.c_str());
  std::printf("\n|---|---|---|---|");
  for (size_t i = 0; i < runs.size(); ++i) std::printf("---|");
  std::printf("\n");
  for (const Reference& p : reference) {
    std::printf("| %s | %s | %.2f | %.3f |", p.series.c_str(), p.quantity.c_str(), p.edge, p.value);
    for (const Run& run : runs)
      std::printf(" %.3f |", at(run, p.edge, p.quantity == "load_kN" ? &Row::load_kN : &Row::neck_ratio));
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  fs::path out = ".", reference_file;
  std::vector<Run> runs;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--out" && i + 1 < argc) {
        out = argv[++i];
      } else if (a == "--reference" && i + 1 < argc) {
        reference_file = argv[++i];
      } else if (const auto eq = a.find('='); eq != std::string::npos) {
        runs.push_back(read_run(a.substr(0, eq), a.substr(eq + 1)));
      } else {
        std::cerr << "usage: rollsim_necking_curve --out DIR [--reference FILE] LABEL=summary.json ...\n";
        return 2;
      }
    }
    if (runs.empty()) throw std::runtime_error("no summary given (LABEL=summary.json)");
    const auto reference = reference_file.empty() ? std::vector<Reference>{} : read_reference(reference_file);
    fs::create_directories(out);
    write_csv(out / "necking.csv", runs);
    write_plots(out, runs, reference);
    print_table(runs, reference);
  } catch (const std::exception& e) {
    std::cerr << "rollsim_necking_curve: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
