// What the window's live plots cost the solver (docs/BENCHMARKS-GUI.md, "Live plot overhead"): the same analysis
// run in the AnalysisWorker thread with the window's RunPlots shown but not connected, shown and connected (signals
// recorded at once, charts redrawn at most every RunPlots::kRefreshMs), and — for contrast — with a chart that appends
// every point as it arrives (QXYSeries::append lays the whole series out again per point). Reports medians over repeats
// (modes interleaved, their order rotating) of the analysis wall time measured inside the core
// (Results::timing.total_s), of the solver thread's CPU time and of the GUI thread's CPU time during the run, and the
// solver thread's price of one queued signal. Prints markdown; asserts nothing.
//
//   xvfb-run -a build/tests/bench/rollsim_gui_plot_bench [--repeats N]
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QThread>
#include <QValueAxis>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include "AnalysisWorker.h"
#include "ResidualPlot.h"
#include "RunPlots.h"
#include "project/Project.h"

using namespace rollsim;
using namespace rollsim::ui;

namespace {

enum class Mode { Unobserved, LivePlots, Unthrottled };
const char* kModeNames[] = {"plots shown, not connected", "RunPlots connected (throttled)",
                            "chart appended point by point"};

struct Case {
  const char* label;
  const char* sample;
  const char* partition;  // "" keeps the sample's
};

struct Sample {
  double analysis_s = 0, run_s = 0;
  double solver_cpu_s = 0;  // CPU time of the worker thread from "assemble" to "recover" (emitting included)
  double gui_cpu_s = 0;     // CPU time of the GUI thread from start to finished (receiving and drawing)
  long cg_iterations = 0;
};

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

Project project_of(const Case& c) {
  Project p = load_project(std::string(ROLLSIM_SOURCE_DIR "/samples/") + c.sample);
  json& s = p.data["solver"];
  s["mode"] = "feti";
  s["preconditioner"] = "none";
  s["cg_tolerance"] = 1e-10;
  s["threads"] = 1;
  if (*c.partition) p.data["bodies"][0]["partition"] = c.partition;
  return p;
}

Sample run_once(const Project& project, Mode mode) {
  AnalysisWorker worker;
  RunPlots plots;
  std::unique_ptr<QtCharts::QChartView> raw;
  if (mode != Mode::Unthrottled) {  // the same window in both: only the connection differs
    plots.resize(1280, 250);
    plots.show();
    if (mode == Mode::LivePlots) plots.watch(&worker);
  } else {
    raw = std::make_unique<QtCharts::QChartView>();
    auto* series = new QtCharts::QLineSeries;
    auto* x = new QtCharts::QValueAxis;
    auto* y = new QtCharts::QLogValueAxis;
    QtCharts::QChart* chart = raw->chart();
    chart->addSeries(series);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    series->attachAxis(x);
    series->attachAxis(y);
    y->setRange(1e-12, 1);
    raw->resize(1280, 250);
    raw->show();
    QObject::connect(&worker, &AnalysisWorker::cgIterations, raw.get(), [series, x](const QVector<CgIteration>& b) {
      for (const CgIteration& c : b) {
        series->append(series->count() + 1, std::max(c.residual, 1e-300));
        x->setRange(0, series->count());
      }
    });
  }
  // let the window be exposed and painted before the run: its first paint is not a cost per iteration
  QElapsedTimer settle;
  settle.start();
  while (settle.elapsed() < 300) QApplication::processEvents(QEventLoop::AllEvents, 50);
  // the worker thread's CPU clock, read on that thread (a direct connection runs in the emitting thread)
  double solver_cpu_begin = 0, solver_cpu_end = 0;
  QObject::connect(
      &worker, &AnalysisWorker::stageStarted, &worker,
      [&](const QString& stage) {
        if (stage == QLatin1String("assemble")) solver_cpu_begin = thread_cpu_seconds();
        if (stage == QLatin1String("recover")) solver_cpu_end = thread_cpu_seconds();
      },
      Qt::DirectConnection);
  RunOutcome outcome;
  QEventLoop loop;
  QObject::connect(&worker, &AnalysisWorker::finished, &loop, [&](const RunOutcome& o) {
    outcome = o;
    loop.quit();
  });
  const double gui_cpu_begin = thread_cpu_seconds();
  worker.start(project);
  loop.exec();
  const double gui_cpu = thread_cpu_seconds() - gui_cpu_begin;
  if (mode == Mode::LivePlots) plots.flush();
  if (!outcome.results || outcome.status != QLatin1String("converged")) {
    std::fprintf(stderr, "run failed: %s %s\n", qPrintable(outcome.status), qPrintable(outcome.message));
    std::exit(1);
  }
  if (mode == Mode::LivePlots &&
      plots.residual_plot()->points(QStringLiteral("cg")) != static_cast<int>(outcome.cg_iterations)) {
    std::fprintf(stderr, "the plot missed points\n");
    std::exit(1);
  }
  Sample out;
  out.analysis_s = outcome.results->timing.total_s;
  out.run_s = outcome.seconds;
  out.solver_cpu_s = solver_cpu_end - solver_cpu_begin;
  out.gui_cpu_s = gui_cpu;
  out.cg_iterations = outcome.cg_iterations;
  return out;
}

/// Microseconds the emitting thread spends per queued signal of one CG iteration, with the plots connected or not
/// (the receiver's work happens later on the GUI thread): what a signal per iteration would cost the solver thread,
/// before the wake-ups of the GUI thread it causes — the reason the worker sends CG iterations in batches.
double emit_cost_us(bool connected) {
  AnalysisWorker worker;
  RunPlots plots;
  if (connected) plots.watch(&worker);
  constexpr int kSignals = 200000;
  double seconds = 0;
  QThread* t = QThread::create([&] {
    QElapsedTimer clock;
    clock.start();
    for (int i = 1; i <= kSignals; ++i) emit worker.cgIterations({{1, i, 1.0 / i}});
    seconds = static_cast<double>(clock.nsecsElapsed()) * 1e-9;
  });
  t->start();
  while (!t->wait(10)) QApplication::processEvents();
  delete t;
  QApplication::processEvents();  // deliver what is queued
  return 1e6 * seconds / kSignals;
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  int repeats = 9;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--repeats") == 0) repeats = std::max(1, std::atoi(argv[i + 1]));
  const std::vector<Case> cases = {
      {"block-indent-dd-2d-50x30, feti 5x3 + block", "block-indent-dd-2d-50x30.json", ""},
      {"cantilever-2d-240x60, feti 16x4", "cantilever-2d-240x60.json", "16x4"},
      {"cantilever-3d-16x16x16, feti 4x4x2", "cantilever-3d-16x16x16.json", "4x4x2"},
  };
  std::printf("platform %s, %d repeats, modes interleaved; median wall time\n\n", qPrintable(app.platformName()),
              repeats);
  std::printf(
      "| case | CG it. | mode | analysis wall [s] | overhead | solver thread CPU [s] | overhead | GUI thread "
      "CPU during the run [s] |\n");
  std::printf("|---|---:|---|---:|---:|---:|---:|---:|\n");
  for (const Case& c : cases) {
    const Project p = project_of(c);
    run_once(p, Mode::Unobserved);  // warm-up: page cache, allocator, BLAS
    std::vector<double> wall[3], cpu[3], gui[3];
    long iterations = 0;
    for (int r = 0; r < repeats; ++r)
      for (int k = 0; k < 3; ++k) {  // the order rotates from repeat to repeat: no mode always follows another
        const Mode m = static_cast<Mode>((r + k) % 3);
        const Sample t = run_once(p, m);
        if (std::getenv("ROLLSIM_BENCH_RAW"))
          std::fprintf(stderr, "%s\t%d\t%.5f\t%.5f\t%.5f\n", c.label, static_cast<int>(m), t.analysis_s, t.solver_cpu_s,
                       t.gui_cpu_s);
        wall[static_cast<int>(m)].push_back(t.analysis_s);
        cpu[static_cast<int>(m)].push_back(t.solver_cpu_s);
        gui[static_cast<int>(m)].push_back(t.gui_cpu_s);
        iterations = t.cg_iterations;
      }
    const double w0 = median(wall[0]), c0 = median(cpu[0]);
    for (int m = 0; m < 3; ++m) {
      const double w = median(wall[m]), cp = median(cpu[m]);
      std::printf("| %s | %ld | %s | %.4f | %+.1f %% | %.4f | %+.1f %% | %.4f |\n", c.label, iterations, kModeNames[m],
                  w, 100 * (w / w0 - 1), cp, 100 * (cp / c0 - 1), median(gui[m]));
    }
    std::fflush(stdout);
  }
  std::printf(
      "\nemitting one queued signal of one CG iteration on the solver thread: %.2f us with nothing connected, %.2f us "
      "with the "
      "plots connected (queued)\n",
      emit_cost_us(false), emit_cost_us(true));
  return 0;
}
