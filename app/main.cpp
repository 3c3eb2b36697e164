// rollsim: the batch command line, and the desktop window (`rollsim gui`, or no arguments).
#include <CLI/CLI.hpp>
#include <iostream>

#include "BenchSuiteCommand.h"
#include "Commands.h"
#include "VtkThreads.h"
#include "base/Blas.h"
#include "base/Memory.h"
#include "base/Schema.h"
#include "project/ProjectSchema.h"
#include "solve/PetscStrategy.h"
#include "solve/SolverStrategy.h"

namespace {
/// `word` as a shell would need it typed again: quoted when it holds anything but plain characters.
std::string shell_word(const std::string& word) {
  if (!word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                                              "-_./=:,+@%") == std::string::npos)
    return word;
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

/// The flags the project schema marks (Field::flag), `--set PATH=VALUE` and `--partition`: each becomes an override
/// of the project, checked by its validation.
void add_project_flags(CLI::App& cmd, rollsim::Overrides& overrides) {
  for (const auto& [path, field] : rollsim::flagged_fields(rollsim::project_schema())) {
    std::string help = field->doc + " (" + path + ")";
    if (!field->choices.empty()) help += ": " + rollsim::one_of(field->choices);
    const std::string flag = "--" + field->flag;
    cmd.add_option_function<std::string>(
        flag,
        [&overrides, path = path, flag](const std::string& v) {
          overrides.sets.push_back({path, v, flag});
        },
        help);
  }
  cmd.add_option_function<std::vector<std::string>>(
      "--set",
      [&overrides](const std::vector<std::string>& sets) {
        for (const std::string& s : sets) {
          const auto eq = s.find('=');
          if (eq == std::string::npos) throw CLI::ValidationError("--set", "expects PATH=VALUE, got '" + s + "'");
          overrides.sets.push_back({s.substr(0, eq), s.substr(eq + 1), "--set"});
        }
      },
      "PATH=VALUE: set any project field, e.g. --set analysis.max_iterations=40 --set bodies[0].partition=2x2 "
      "(the reference: rollsim schema)");
  cmd.add_option_function<std::string>(
      "--partition", [&overrides](const std::string& v) { overrides.partition = v; },
      "[BODY=]SPEC: subdomains for feti, e.g. 4x4, 2x2x1, metis:16 (default body: the first; a process: the "
      "slab)");
}
}  // namespace

int main(int argc, char** argv) {
  using namespace rollsim::app;
  rollsim::keep_freed_memory_for_reuse();
#ifndef ROLLSIM_HAVE_GUI
  rollsim::run_vtk_sequentially();  // the batch binary only writes with VTK (VtkThreads.h)
#endif
  struct EndProcesses {  // PETSc and MPI end after the command, whichever return it took (solver `petsc`)
    ~EndProcesses() { rollsim::finish_processes(); }
  } end_processes;
  CLI::App cli{"rollsim: finite element simulation of flat hot rolling"};
  cli.require_subcommand(0, 1);
  bool version = false;
  cli.add_flag("--version", version, "print the version and the BLAS in use");

  RunOptions run;
  for (int i = 0; i < argc; ++i) run.command += (i ? " " : "") + shell_word(argv[i]);
  auto* cmd_run = cli.add_subcommand("run", "solve a project and write summary.json and result.vtu");
  cmd_run->add_option("project", run.project, "project file (JSON)")->required();
  cmd_run->add_option("--out", run.out, "output directory (default: the project's output.dir or results/<name>)");
  add_project_flags(*cmd_run, run.overrides);
  cmd_run->add_flag("--quiet", run.quiet, "no progress on stderr");

  std::string check_file;
  auto* cmd_check = cli.add_subcommand("check", "validate a project without solving");
  cmd_check->add_option("project", check_file, "project file (JSON)")->required();

  RunOptions mesh;
  auto* cmd_mesh =
      cli.add_subcommand("mesh", "write the meshes of a project (bodies, subdomains) as mesh.vtu, without solving");
  cmd_mesh->add_option("project", mesh.project, "project file (JSON)")->required();
  cmd_mesh->add_option("--out", mesh.out, "output directory (default: the project's output.dir or results/<name>)");
  cmd_mesh->add_option_function<std::string>(
      "--partition", [&mesh](const std::string& v) { mesh.overrides.partition = v; },
      "[BODY=]SPEC: show this partition, e.g. 4x4, metis:16");
  cmd_mesh->add_flag("--quiet", mesh.quiet, "no summary line on stderr");

  BenchOptions bench;
  auto* cmd_bench = cli.add_subcommand("bench", "time assembly, ordering, factorization and solve: skyline vs CHOLMOD");
  cmd_bench->add_option("samples", bench.samples, "project files");
  cmd_bench->add_option("--repeat", bench.repeat, "repetitions (the median is reported)")->check(CLI::Range(1, 100));
  cmd_bench->add_option("--threads", bench.threads, "BLAS threads")->check(CLI::Range(1, 256));
  cmd_bench->add_option("--csv", bench.csv, "also write the table as CSV");
  auto bench_suite =
      add_bench_suites(*cmd_bench, argc, argv);  // `rollsim bench accuracy | stability` (BenchSuiteCommand.cpp)

  std::string export_project, export_out;
  auto* cmd_export = cli.add_subcommand("export-ccx", "write the model as CalculiX input (.inp)");
  cmd_export->add_option("project", export_project, "project file (JSON)")->required();
  cmd_export->add_option("out", export_out, "output .inp file")->required();

  auto* cmd_schema = cli.add_subcommand("schema", "print the project file reference (markdown)");

  GuiOptions gui{"", "", "", false, false, "", argc, argv};
  auto* cmd_gui = cli.add_subcommand("gui", "open the desktop window (the default without arguments)");
  cmd_gui->add_option("project", gui.project, "project file (JSON); default: the built-in default project");
  cmd_gui->add_option("--screenshot", gui.screenshot, "render, save the whole window as PNG and exit");
  cmd_gui->add_option("--size", gui.size, "window size WxH (default 1280x800)");
  cmd_gui->add_flag("--run", gui.run, "run the analysis before the screenshot (results and residual plot shown)");
  cmd_gui->add_flag("--partitions", gui.partitions, "show the partition panel, the view coloured by subdomain");
  cmd_gui->add_option("--color-by", gui.color_by,
                      "after --run: colour the view by this result field (e.g. von_mises, plastic_strain)");

#if defined(ROLLSIM_HAVE_GUI) || defined(ROLLSIM_GUI_BESIDE)
  if (argc == 1) return gui_command(gui);  // no arguments: the window
#endif
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cli.exit(e) == 0 ? 0 : 2;
  }
  if (version) {
    std::cout << "rollsim " << ROLLSIM_VERSION << "\nBLAS: " << rollsim::blas_description() << "\n";
    return 0;
  }
  try {
    if (*cmd_run) return run_command(run);
    if (*cmd_check) return check_command(check_file);
    if (*cmd_mesh) return mesh_command(mesh);
    if (*cmd_schema) return schema_command();
    if (*cmd_bench) {
      if (auto code = bench_suite()) return *code;
      if (bench.samples.empty()) {
        std::cerr << "rollsim: error: bench: give project files, or a suite: accuracy, stability\n";
        return 2;
      }
      return bench_command(bench);
    }
    if (*cmd_export) return export_ccx_command(export_project, export_out);
    if (*cmd_gui) return gui_command(gui);
  } catch (const std::exception& e) {
    std::cerr << "rollsim: internal error: " << e.what() << "\n";
    return 1;
  }
  std::cout << cli.help();
  return 0;
}
