#pragma once
// One case of a benchmark suite (`rollsim bench accuracy | stability`): a complete project (a JSON variant of a
// validation problem), how its answer is measured, what it is compared with, and the error it must stay within.
#include <functional>
#include <limits>
#include <string>

#include "analysis/Results.h"
#include "base/Schema.h"
#include "model/Model.h"

namespace rollsim::bench {

/// How much of a suite to run: tiny (the ctest smoke run, seconds), quick (minutes), full (the committed tables).
enum class SuiteSize { tiny, quick, full };

/// The quantity a case measures and, when a closed form exists, its exact value (NaN otherwise: the suite then
/// takes the value of the case named by SuiteCase::reference_case).
struct Measure {
  double value = std::numeric_limits<double>::quiet_NaN();
  double exact = std::numeric_limits<double>::quiet_NaN();
};
using MeasureFn = std::function<Measure(const Model&, const Results&)>;

struct SuiteCase {
  std::string suite;    // accuracy, stability
  std::string family;   // the problem: cantilever, kirsch, hertz, stiffness-ratio, poisson, …
  std::string variant;  // what is varied, in words: "h=0.02", "E2/E1=1e4", "nu=0.4999 bbar"
  std::string mode;     // solver label: skyline, direct, mixed, feti-none, feti-lumped, feti-dirichlet (+:selective)
  double level = 0;     // the swept parameter as a number (elements through the depth, ratio, ν, …)
  double cg_tolerance = 0;  // 0: a direct mode, no tolerance
  json project;             // complete project file (solver settings included)
  MeasureFn measure;
  std::string quantity;        // what `measure` returns, in words
  std::string reference_case;  // name() of the case whose value is the reference when there is no closed form
  std::string reference_kind;  // "closed form (Hertz p0)", "direct, 2x finer mesh", …
  double bound = std::numeric_limits<double>::infinity();  // stated relative error bound (stability)
  bool compare_to_direct = false;  // also solve with `direct` on the same model: the algebraic (solver) error
  double distortion = 0;           // interior nodes moved randomly by up to this fraction of the element size
  std::string if_wrong;            // the likely cause, in words, when the answer exceeds its bound
  bool reference_only = false;     // a reference solution: listed, not plotted

  std::string name() const { return family + "/" + variant + "/" + mode + tolerance_label(); }
  std::string tolerance_label() const;
};

}  // namespace rollsim::bench
