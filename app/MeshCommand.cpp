// `rollsim check` and `rollsim mesh`: project -> model, validated, and its meshes written without solving.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "Commands.h"
#include "VtuWriter.h"
#include "io/AtomicFile.h"
#include "io/PartitionReportJson.h"
#include "model/DofMap.h"
#include "partition/PartitionReport.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"
#include "project/RunForecast.h"
#include "project/RunProject.h"

namespace rollsim::app {

namespace {
int invalid(const std::string& message) {
  std::cerr << "rollsim: error: " << message << "\n";
  return 2;
}

/// partition.json beside mesh.vtu when a body is partitioned: the window's partition table (counts and predicted
/// cost against one domain) for batch users. An error message, or empty.
std::string write_partition_report(const std::filesystem::path& file, const Model& model) {
  std::vector<BodyPartitionReport> reports;
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    const Body& b = model.bodies[i];
    if (b.partition.num_subdomains <= 1) continue;
    const DofMap dofs(b, static_cast<int>(i), model.displacements);
    PartitionReporter reporter(b, dofs);
    reports.push_back({b.name, reporter.update(b.partition)});
  }
  if (reports.empty()) return {};
  try {
    write_file_atomically(file, partition_report_json(reports));
  } catch (const std::exception& e) {
    return "cannot write " + file.string() + ": " + e.what();
  }
  return {};
}

/// Characters (UTF-8 code points) of `s`: what a terminal column counts.
size_t columns(const std::string& s) {
  return static_cast<size_t>(std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

/// The process's facts, aligned, and the forecast's line.
void print_forecast(const RunForecast& f) {
  size_t name = 0, value = 0;
  for (const ProcessFact& fact : f.facts)
    name = std::max(name, columns(fact.name)), value = std::max(value, columns(fact.value));
  for (const ProcessFact& fact : f.facts)
    std::cout << "  " << fact.name << std::string(name - columns(fact.name) + 2, ' ') << fact.value
              << std::string(value - columns(fact.value) + 2, ' ') << (fact.warning ? "(!) " : "") << fact.note << "\n";
  std::cout << "forecast: " << forecast_line(f) << "\n";
}
}  // namespace

int check_command(const std::string& file) {
  try {
    const Project p = load_project(file);
    const Model m = build_model(p);
    // every test that needs no solve: a pass the roll cannot bite is refused here as `run` would refuse it (the
    // forecast starts the process and holds its refusal)
    const RunForecast forecast = forecast_run(p.config(), m);
    if (const RunStatus& refused = forecast.refusal; !refused.ok()) {
      std::cerr << "rollsim: " << to_string(refused.status) << ": " << refused.message << "\n";
      return exit_code(refused.status);
    }
    std::cout << file << ": valid (" << m.bodies.size() << " bodies, " << m.total_nodes() << " nodes, "
              << m.total_elements() << " elements)\n";
    print_forecast(forecast);
    return 0;
  } catch (const ProjectError& e) {
    return invalid(e.what());
  }
}

int mesh_command(const RunOptions& o) {
  Model model;
  Project project;
  try {
    project = load_project(o.project, o.overrides);
    model = build_model(project);
  } catch (const ProjectError& e) {
    return invalid(e.what());
  }
  for (const auto& w : model.warnings) std::fprintf(stderr, "rollsim: warning: %s\n", w.c_str());
  const auto file = output_dir(project, o) / "mesh.vtu";
  try {
    std::filesystem::create_directories(file.parent_path());
    write_mesh_vtu(file, model);
  } catch (const std::exception& e) {
    return invalid("cannot write " + file.string() + ": " + e.what());
  }
  if (const auto err = write_partition_report(file.parent_path() / "partition.json", model); !err.empty())
    return invalid(err);
  if (!o.quiet)
    std::fprintf(stderr, "rollsim: %s: %zu bodies, %ld nodes, %ld elements\n", project.name().c_str(),
                 model.bodies.size(), model.total_nodes(), model.total_elements());
  std::cout << file.string() << "\n";
  return 0;
}

std::filesystem::path output_dir(const Project& p, const RunOptions& o) {
  if (o.out) return *o.out;
  if (const auto dir = p.config().output.dir) return *dir;
  return std::filesystem::path("results") / p.name();
}

}  // namespace rollsim::app
