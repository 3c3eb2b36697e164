#include "BenchSuiteCommand.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "Commands.h"
#include "bench/SuiteReport.h"
#include "bench/Suites.h"
#include "io/AtomicFile.h"

#ifdef ROLLSIM_HAVE_GUI
#include "BenchCharts.h"
#endif

namespace rollsim::app {

namespace {

struct SuiteOptions {
  std::string size = "quick";
  std::string out = "results/bench";
  std::string family;
  std::string image_link;  // prefix of the plots' paths in the markdown (default: beside it)
  double timeout = 300;
  bool quiet = false;
};

void progress_line(size_t done, size_t total, const bench::SuiteCase& c, const bench::CaseOutcome& o) {
  std::fprintf(stderr, "[%zu/%zu] %s: %s", done, total, c.name().c_str(), o.status.c_str());
  if (std::isfinite(o.wall_s)) std::fprintf(stderr, " %.3f s", o.wall_s);
  if (o.cg_iterations > 0) std::fprintf(stderr, ", %ld CG", o.cg_iterations);
  if (o.status != "converged") std::fprintf(stderr, " (%s)", o.message.c_str());
  std::fprintf(stderr, "\n");
}

#ifdef ROLLSIM_HAVE_GUI
/// One PNG per family: every mode's runs, the family's front.
void write_plots(const std::filesystem::path& dir, const std::string& suite,
                 const std::vector<bench::CaseResult>& results, const std::vector<bool>& pareto) {
  std::vector<std::string> families;
  for (const auto& r : results)
    if (families.empty() || families.back() != r.c.family) families.push_back(r.c.family);
  for (const std::string& f : families) {
    std::vector<ui::TimeErrorSeries> series;
    std::vector<ui::TimeErrorPoint> front;
    for (size_t i = 0; i < results.size(); ++i) {
      const auto& r = results[i];
      if (r.c.family != f || r.c.reference_only || r.o.status != "converged" || !std::isfinite(r.error)) continue;
      auto it = std::find_if(series.begin(), series.end(), [&](auto& s) { return s.name == r.c.mode; });
      if (it == series.end()) {
        series.push_back(ui::TimeErrorSeries{r.c.mode, {}});
        it = series.end() - 1;
      }
      it->points.push_back({r.o.wall_s, r.error});
      if (pareto[i]) front.push_back({r.o.wall_s, r.error});
    }
    if (series.empty()) continue;
    const auto& any = *std::find_if(results.begin(), results.end(), [&](auto& r) { return r.c.family == f; });
    ui::write_time_error_png(dir / (suite + "-" + f + ".png"),
                             f + ": " + any.c.quantity + " — run time against error (" + any.c.reference_kind + ")",
                             series, front);
  }
}
#endif

int run(const std::string& suite, const SuiteOptions& o) {
  std::vector<bench::SuiteCase> cases;
  try {
    cases = bench::suite_cases(suite, bench::suite_size(o.size), o.family);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "rollsim: error: bench %s: %s\n", suite.c_str(), e.what());
    return 2;
  }
  const std::filesystem::path dir(o.out);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    std::fprintf(stderr, "rollsim: error: cannot create output directory %s: %s\n", o.out.c_str(),
                 ec.message().c_str());
    return 2;
  }
  const size_t total = cases.size();
  const auto results = bench::run_suite(cases, o.timeout, [&](size_t done, auto& c, auto& outcome) {
    if (!o.quiet) progress_line(done, total, c, outcome);
  });
  const std::vector<bool> pareto = bench::pareto_front(results);
  write_file_atomically(dir / (suite + ".csv"), bench::suite_csv(results, pareto));
  const std::string md = suite == "accuracy" ? bench::accuracy_markdown(results, pareto, o.image_link + suite + "-")
                                             : bench::stability_markdown(results);
  write_file_atomically(dir / (suite + ".md"), md);
#ifdef ROLLSIM_HAVE_GUI
  if (suite == "accuracy") write_plots(dir, suite, results, pareto);
#endif
  int broken = 0;
  for (const auto& r : results) broken += r.verdict == bench::Verdict::broken;
  std::fprintf(stderr, "rollsim: bench %s: %zu cases, %d broken; %s\n", suite.c_str(), total, broken,
               (dir / (suite + ".csv")).string().c_str());
  return broken > 0 ? 3 : 0;
}

}  // namespace

std::function<std::optional<int>()> add_bench_suites(CLI::App& bench, int argc, char** argv) {
  auto options = std::make_shared<SuiteOptions>();
  std::vector<std::pair<CLI::App*, std::string>> commands;
  for (const std::string& suite : bench::suite_names()) {
    CLI::App* cmd = bench.add_subcommand(
        suite, suite == "accuracy" ? "run time against error for every solver mode, preconditioner and update policy"
                                   : "the stability stress suite: each case converged, or failed with a reason");
    cmd->add_option("--size", options->size,
                    "tiny (seconds), quick (about one CPU minute) or full (the committed tables)");
    cmd->add_option("--out", options->out, "output directory for SUITE.csv, SUITE.md and the plots");
    cmd->add_option("--family", options->family, "only this family of cases");
    cmd->add_option("--timeout", options->timeout, "seconds before a case is killed")->check(CLI::PositiveNumber);
    cmd->add_option("--image-link", options->image_link, "prefix of the plots' paths written in SUITE.md");
    cmd->add_flag("--quiet", options->quiet, "no progress on stderr");
    commands.emplace_back(cmd, suite);
  }
  return [options, commands, argc, argv]() -> std::optional<int> {
    for (const auto& [cmd, suite] : commands) {
      if (!*cmd) continue;
#ifdef ROLLSIM_GUI_BESIDE
      if (suite == "accuracy") return hand_over_to_window(argc, argv);  // its plots are Qt Charts
#else
      (void)argc, (void)argv;
#endif
      return run(suite, *options);
    }
    return std::nullopt;
  };
}

}  // namespace rollsim::app
