#pragma once
// `rollsim bench accuracy | stability [--size tiny|quick|full] [--out DIR] [--family NAME] [--timeout S]`: the
// benchmark suites, registered as subcommands of `bench` so that `rollsim bench PROJECT…` (the factorization
// stages, BenchCommand.cpp) keeps its form.
#include <functional>
#include <optional>

namespace CLI {
class App;
}  // namespace CLI

namespace rollsim::app {

/// Adds the suites under `bench`; the returned function, called after parsing, runs the suite that was named and
/// returns its exit code (0: every case ok, wrong or failed with a reason; 3: a case crashed or gave NaN;
/// 2: invalid options), or nothing when no suite was named. The batch binary of a build with the window hands the
/// accuracy suite (`argc`, `argv`: the command line) over to rollsim-gui, whose Qt Charts draw its plots.
std::function<std::optional<int>()> add_bench_suites(CLI::App& bench, int argc, char** argv);

}  // namespace rollsim::app
